delta=10
width: 0.5
n: 3
axiom: FF[A][B]
A -> [[+A{.C.]GC.}]
B -> [[-B{.C.]GC.}]
C -> GC
