// A three-dimensional bush with leaves, ABOP fig. 1.25 (p. 26).
// Source: seed 000 ("Modelowanie drzewa") and seed 002 (the shrub of
// "Digital Design of Nature", fig. 5.5). `!` thins each new branch by the
// width factor; `'` steps the colour (stem 0, leaves 3 and on).
// test: n = 4 (the full model, n = 7, is built by 'make gallery', not in CI)
// expect: segments 3891, polygons 1284
// volume: 10618.8 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n=7, δ=22.5°
width: 0.3
width factor: 0.75
ω: A
p1: A → [&FL!A]/////'[&FL!A]///////'[&FL!A]
p2: F → S/////F
p3: S → FL
p4: L → ['''^^{-f+f+f-|-f+f+f}]
