n=2
angle: 90°
axiom: F
