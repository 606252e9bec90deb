angle: 20
angle factor: 16
ω: F
