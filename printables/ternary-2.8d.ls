// Ternary tree with tropism, ABOP fig. 2.8d, Table 2.3 case d (p. 60).
// ABOP's tropism vector (−0.61,0.77,−0.19) is in cpfg's Y-up frame; lsolid is Z-up
// (docs/turtle.md): (x, y, z) in ABOP is (x, -z, y) here.
// test: n = 3 (the full model, n = 6, is built by 'make gallery', not in CI)
// expect: segments 1457, polygons 0
// volume: 3821.3 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
#define d1 180  /* divergence angle 1 */
#define d2 252  /* divergence angle 2 */
#define a 36    /* branching angle */
#define lr 1.07   /* elongation rate */
#define vr 1.732 /* width increase rate */
n = 6
tropism: -0.61, 0.19, 0.77
elasticity: 0.40
ω : !(1)F(200)/(45)A
p1 : A : * → !(vr)F(50)[&(a)F(50)A]/(d1)[&(a)F(50)A]/(d2)[&(a)F(50)A]
p2 : F(l) : * → F(l*lr)
p3 : !(w) : * → !(w*vr)
