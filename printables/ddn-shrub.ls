// The small shrub of seed 002 ("Digital Design of Nature", §5.4, fig. 5.5,
// courtesy of P. Prusinkiewicz), written with its ::= arrows. The scanned
// text garbles the leaf rule; this is ABOP fig. 1.25's, which it copies.
// As printed, only the first branch of A thins with `!`.
// test: n = 4 (the full model, n = 7, is built by 'make gallery', not in CI)
// expect: segments 3891, polygons 1284
// volume: 13429.4 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n=7, δ=22.5°
width: 0.3
width factor: 0.75
ω: A
A ::= [&FL!A]/////'[&FLA]///////'[&FLA]
F ::= S/////F
S ::= FL
L ::= ['''∧∧{-f+f+f-|-f+f+f}]
