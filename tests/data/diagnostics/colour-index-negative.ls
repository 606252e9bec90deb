n=1
axiom: A(1)
A(x) → F,(x-2)F
