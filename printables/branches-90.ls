// The bracket example of seed 004: F[+F]F[+F]F[+F]F[+F] with σ = 90°.
// expect: segments 8, polygons 0
n=0, σ=90°
width: 0.3
ω: F[+F]F[+F]F[+F]F[+F]
