// The tree of seed 003 ("[Houdini] L-System 初步了解"): ABOP fig. 1.24d in
// Houdini's notation, premise and -> arrows.
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
premise: X
X->F[+X]F[-X]+X
F->FF
