// The tree F[+F][-F[-F]F]F[+F][-F] (seed 000, "Modelowanie drzewa"): a
// bracketed string drawn as it is, without productions.
// expect: segments 8, polygons 0
n=0, δ=25.7°
width: 0.2
ω: F[+F][-F[-F]F]F[+F][-F]
