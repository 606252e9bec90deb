// The polygon example of seed 004: F{-f+f+f-|-f+f+f} with σ = 30°, a stem
// and a filled leaf.
// expect: segments 1, polygons 1
// volume: 6071.8 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n=0, σ=30°
width: 0.2
ω: F{-f+f+f-|-f+f+f}
