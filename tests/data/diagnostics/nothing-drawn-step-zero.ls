n=2
step: 0
axiom: F
F → F[+F]F
