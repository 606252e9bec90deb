// Sympodial tree (Aono and Kunii), ABOP fig. 2.7a, Table 2.2 case a (p. 59).
// Each step ends the axis and continues it by two lateral branches.
// 2^10 - 1 = 1023 segments at n = 10.
// test: n = 6 (the full model, n = 10, is built by 'make gallery', not in CI)
// expect: segments 1023, polygons 0
// volume: 3846.2 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
#define r1 0.9  /* contraction ratio 1 */
#define r2 0.7  /* contraction ratio 2 */
#define a1 5  /* branching angle 1 */
#define a2 65  /* branching angle 2 */
#define wr 0.707 /* width decrease rate */
n = 10
// cpfg widths are pixels; this maps width 10 to a trunk 0.25 units thick.
width scale: 0.025
ω : A(1, 10)
p1 : A(l, w) : * → !(w)F(l)[&(a1)B(l*r1, w*wr)]/(180)[&(a2)B(l*r2, w*wr)]
p2 : B(l, w) : * → !(w)F(l)[+(a1)$B(l*r1, w*wr)][-(a2)$B(l*r2, w*wr)]
