// A leaf built from { [ ] . G } (seed 000, "Modelowanie liścia"; ABOP §5.1,
// fig. 5.5). G draws a vein without adding a vertex; each ray's tip is a
// vertex. The lecture prints the dots between the brackets,
// {[++++G].[++GG].[+GGG].[GGGGG].[-GGG].[--GG].[-G.]}, which marks the
// base six times and gives a degenerate polygon; here each `.` stands at its
// ray's tip, inside the brackets, as the last ray (`[-G.]`) already has it.
// expect: segments 17, polygons 1
// volume: 10593.5 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
n=0, δ=18°
width: 0.25
ω: {[++++G.][++GG.][+GGG.][GGGGG.][-GGG.][--GG.][-G.]}
