# --- L-System Parser/Mutator --- Lj Lapre ----------------------------------
#
# Ternary skeleton
#
15
30
20
#
c(12)FA
#
A=!(.9)t(.4)FB>(94)B>(132)B
B=[&t(.4)F$A]
F='(1.25)F'(.8)
@
