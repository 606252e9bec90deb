# --- L-System Parser/Mutator --- Lj Lapre ----------------------------------
5       # recursion depth
18      # angle
50      # thickness as % of length
#
c(12)p
#
p=i++[p+o]--->>[--l]i[++l]--[po]+++po
i=Fs[>>&&l][>>^^l]Fs
s=sFs
l=[c(8){++f--ff--f++|++f--ff--f}]
o=[&!c(12)e>w>>>>w>>>>w>>>>w>>>>w]
e=FF
w=[c(3)^!F][c(5)&&&&{---f+++f|---f+++f}]
@
