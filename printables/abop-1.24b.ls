// Bracketed plant, ABOP fig. 1.24b (p. 25); seed 000 ("Modelowanie drzewa").
// A planar figure: it lies in the XZ plane, as ABOP draws it seen from the front.
// test: n = 3 (the full model, n = 5, is built by 'make gallery', not in CI)
// expect: segments 3125, polygons 0
// volume: 8884.3 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n=5, δ=20°
width: 1
F
F → F[+F]F[-F][F]
