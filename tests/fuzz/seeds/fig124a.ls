n=1
ω: F
F → F[+F]F[-F]F
δ=25
width: 0.3
