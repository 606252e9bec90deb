// The rectangle path of seed 003 ("[Houdini] L-System 初步了解"), written
// as Houdini users write it. X marks a place and draws nothing. The post
// prints X's rule once as X->F[x] and then as X->F[X]; this is the second.
// expect: segments 34, polygons 0
// volume: 524.1 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n = 3
δ = 90
F
F->F[-XF]F
X->F[X]
