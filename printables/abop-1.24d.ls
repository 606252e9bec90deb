// Bracketed plant, ABOP fig. 1.24d (p. 25); seed 000 ("Modelowanie drzewa")
// and seed 003, which draws its first steps by hand.
// A planar figure: it lies in the XZ plane, as ABOP draws it seen from the front.
// test: n = 4 (the full model, n = 7, is built by 'make gallery', not in CI)
// expect: segments 4118, polygons 0
// volume: 3009.9 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n=7, δ=20°
width: 1
X
X → F[+X]F[-X]+X
F → FF
