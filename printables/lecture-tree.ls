// The tree F[+F][-F[-F]F]F[+F][-F] (seed 000, "Modelowanie drzewa"): a
// bracketed string drawn as it is, without productions.
// expect: segments 8, polygons 0
// volume: 8616.4 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n=0, δ=25.7°
width: 0.2
ω: F[+F][-F[-F]F]F[+F][-F]
