# --- L-System Parser/Mutator --- Lj Lapre ----------------------------------
29
5
10
#
&(90)+(90)a
#
a=F[+(45)l][-(45)l]^;a
#			apical delay
l=j
j=h
h=s
s=d
d=x
x=a
#
F='(1.17)F'(.855)	# internode elongation rate
@
