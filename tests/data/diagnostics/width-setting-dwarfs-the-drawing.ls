width: 1e200
axiom: FF
