# --- L-System Parser/Mutator --- Lj Lapre ----------------------------------
18      # recursion depth
10      # angle
10      # thickness as % of length
#
c(12)FFFFFFc(8)[A][B]
#
A=[+A{.].C.}
B=[-B{.].C.}
C=gC
@
