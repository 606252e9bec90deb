// Ternary tree with tropism, ABOP fig. 2.8a, Table 2.3 case a (p. 60).
// ABOP's tropism vector (0,−1,0) is in cpfg's Y-up frame; lsolid is Z-up
// (docs/turtle.md): (x, y, z) in ABOP is (x, -z, y) here.
// test: n = 3 (the full model, n = 6, is built by 'make gallery', not in CI)
// expect: segments 1457, polygons 0
// volume: 1108.7 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
#define d1 94.74  /* divergence angle 1 */
#define d2 132.63  /* divergence angle 2 */
#define a 18.95    /* branching angle */
#define lr 1.109   /* elongation rate */
#define vr 1.732 /* width increase rate */
n = 6
tropism: 0, 0, -1
elasticity: 0.22
ω : !(1)F(200)/(45)A
p1 : A : * → !(vr)F(50)[&(a)F(50)A]/(d1)[&(a)F(50)A]/(d2)[&(a)F(50)A]
p2 : F(l) : * → F(l*lr)
p3 : !(w) : * → !(w*vr)
