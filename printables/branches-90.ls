// The bracket example of seed 004: F[+F]F[+F]F[+F]F[+F] with σ = 90°.
// expect: segments 8, polygons 0
// volume: 7261.0 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n=0, σ=90°
width: 0.3
ω: F[+F]F[+F]F[+F]F[+F]
