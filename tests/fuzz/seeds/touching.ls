n=2, δ=90°
width: 1
ω: F[+f-F]
base: none
