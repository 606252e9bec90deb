recursion 1
angle 30
thickness 1e308
axiom F
