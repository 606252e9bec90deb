n=1
axiom X
X -> FX
