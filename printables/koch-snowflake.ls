// The Koch snowflake of seed 004 ("Lindenmayer Systems: an efficient
// implementation"): axiom F--F--F, F → F+F--F+F, σ = 60°. The talk draws
// iterations 0 to 3; this is 4. A planar figure in the XZ plane.
// test: n = 3 (the full model, n = 4, is built by 'make gallery', not in CI)
// expect: segments 768, polygons 0
// volume: 4185.9 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n=4, σ=60°
width: 1
ω: F--F--F
F → F+F--F+F
