n=2
angle: 20
n=3
ω: F
