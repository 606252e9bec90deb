// 3D Hilbert curve as a cube, order 3.
// Source: seed 000 ("Hilbert Space Filling Curve"), ABOP fig. 1.19 (p. 20).
// 511 unit segments through the 512 points of a 7 x 7 x 7 lattice box.
// expect: segments 511, polygons 0
// volume: 48308.6 mm³ as the test builds it (within 1%)
// Print settings: 80 mm on the longest side, walls of 0.8 mm;
// it stands on its bottom face.
size: 80mm
wall: 0.8mm
base: none
n=3, δ=90°
width: 0.3
A
A → B-F+CFC+F-D&F^D-F+&&CFC+F+B//
B → A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//
C → |D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//
D → |CFB-F+B|FA&F^A&&FB-F+B|FC//
