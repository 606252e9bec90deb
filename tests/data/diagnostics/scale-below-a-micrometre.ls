n=0
axiom: FF
