// 3D Hilbert curve as a cube.
// Source: seed 000 (Polish lecture on 3D L-systems, "Hilbert Space Filling
// Curve"), ABOP fig. 1.19 (p. 20). Order n visits 8^n cells: 8^n - 1 unit
// segments (63 at n = 2, 511 at n = 3).
// expect: segments 63, polygons 0
// volume: 26947.5 mm³ as the test builds it (within 1%)
// Print settings: 60 mm on the longest side, walls of 0.8 mm;
// it stands on its bottom face.
size: 60mm
wall: 0.8mm
base: none
n=2, δ=90°
width: 0.3
A
A → B-F+CFC+F-D&F^D-F+&&CFC+F+B//
B → A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//
C → |D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//
D → |CFB-F+B|FA&F^A&&FB-F+B|FC//
