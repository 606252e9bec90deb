// The rectangle path of seed 003 ("[Houdini] L-System 初步了解"), written
// as Houdini users write it. X marks a place and draws nothing. The post
// prints X's rule once as X->F[x] and then as X->F[X]; this is the second.
// expect: segments 34, polygons 0
n = 3
δ = 90
F
F->F[-XF]F
X->F[X]
