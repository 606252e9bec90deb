// Ternary tree with tropism, ABOP fig. 2.8c, Table 2.3 case c (p. 60).
// ABOP's tropism vector (−0.02,−1,0) is in cpfg's Y-up frame; lsolid is Z-up
// (docs/turtle.md): (x, y, z) in ABOP is (x, -z, y) here.
// test: n = 3 (the full model, n = 8, is built by 'make gallery', not in CI)
// expect: segments 13121, polygons 0
// volume: 390.9 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
#define d1 112.5  /* divergence angle 1 */
#define d2 157.5  /* divergence angle 2 */
#define a 22.5    /* branching angle */
#define lr 1.790   /* elongation rate */
#define vr 1.732 /* width increase rate */
n = 8
tropism: -0.02, 0, -1
elasticity: 0.27
ω : !(1)F(200)/(45)A
p1 : A : * → !(vr)F(50)[&(a)F(50)A]/(d1)[&(a)F(50)A]/(d2)[&(a)F(50)A]
p2 : F(l) : * → F(l*lr)
p3 : !(w) : * → !(w*vr)
