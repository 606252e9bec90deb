// A plant with flowers, ABOP fig. 1.26 (p. 27); seed 000 ("Japońskie
// drzewo"). Multi-character modules: each predecessor's name is declared by
// the production itself. ABOP's wedge pitches with &&&&; the lecture's
// second slide prints &&& (its first prints &&&&).
// test: n = 3 (the full model, n = 5, is built by 'make gallery', not in CI)
// expect: segments 533, polygons 327
// volume: 2601.8 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n=5, δ=18°
width: 0.15
ω : plant
p1 : plant → internode + [ plant + flower ] - - //
     [ - - leaf ] internode [ + + leaf ] -
     [ plant flower ] + + plant flower
p2 : internode → F seg [ // & & leaf ] [ // ^ ^ leaf ] F seg
p3 : seg → seg F seg
p4 : leaf → [ ' { +f-ff-f+ | +f-ff-f } ]
p5 : flower → [ & & & pedicel ' / wedge //// wedge //// wedge //// wedge //// wedge ]
p6 : pedicel → FF
p7 : wedge → [ ' ^ F ] [ { & & & & -f+f | -f+f } ]
