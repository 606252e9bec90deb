// Honda's monopodial tree, ABOP fig. 2.6d, Table 2.1 case d (p. 56).
// Source: seed 000 ("Opis geometrii drzewa (H. Honda)"), which prints
// case a; cases b to d change r2, a0 and a2 as Table 2.1 gives them.
// 2^10 - 1 = 1023 segments at n = 10.
// test: n = 7 (the full model, n = 10, is built by 'make gallery', not in CI)
// expect: segments 1023, polygons 0
// volume: 2439.8 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
#define r1 0.9   /* contraction ratio for the trunk */
#define r2 0.7   /* contraction ratio for branches */
#define a0 30    /* branching angle from the trunk */
#define a2 -30   /* branching angle for lateral axes */
#define d 137.5  /* divergence angle */
#define wr 0.707 /* width decrease rate */
n = 10
// cpfg widths are pixels; this maps width 10 to a trunk 0.25 units thick.
width scale: 0.025
ω : A(1, 10)
p1 : A(l, w) : * → !(w)F(l) [ &(a0)B(l*r2, w*wr) ] /(d)A(l*r1, w*wr)
p2 : B(l, w) : * → !(w)F(l) [ -(a2)$C(l*r2, w*wr) ] C(l*r1, w*wr)
p3 : C(l, w) : * → !(w)F(l) [ +(a2)$B(l*r2, w*wr) ] B(l*r1, w*wr)
