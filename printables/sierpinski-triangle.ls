// The Sierpinski triangle of seed 004 ("Lindenmayer Systems: an efficient
// implementation"): A → B-A-B, B → A+B+A, where A and B both draw. The talk
// prints σ = 90°, which does not close the triangle; the arrowhead curve
// needs 60° (ABOP fig. 1.10b), which is used here.
// test: n = 4 (the full model, n = 6, is built by 'make gallery', not in CI)
// expect: segments 729, polygons 0
// volume: 14968.2 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n=6, σ=60°
width: 1
aliases: A=F B=F
ω: A
A → B-A-B
B → A+B+A
