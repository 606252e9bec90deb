n=0
scale: 1e-300mm
axiom: FF
