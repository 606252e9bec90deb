delta=22.5
stemsize=1e308
axiom: F
p1: F -> FF
