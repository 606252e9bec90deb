// Tree B of seed 001 ("Modeling a Tree using L-System", 2008), with the
// blog's own symbols and setting names, plus an alias block. The blog
// breaks its second rule over a line; here it stands on one.
// test: n = 5 (the full model, n = 10, is built by 'make gallery', not in CI)
// expect: segments 2037, polygons 2046
// volume: 7271.9 mm³ as the test builds it (within 1%)
// Print settings: 100 mm on the longest side, walls of 0.8 mm,
// and a disc under it where it would tip over.
size: 100mm
wall: 0.8mm
base: auto
aliases:
  f = F   /* create branch */
  v = &   /* pitch down */
  < = \   /* twist left */
  > = /   /* twist right */
Angle : 30
Iterations: 10
Branch radius: 0.01
Branch radius reduction: 0.001
Branch length (height): 0.16
Initial value : fA
Production rules : A = f[^Bl]>>[^Bl]>>A, B = f[-Bl]B
// The blog does not print its leaf; this one is ABOP's (fig. 1.25).
homomorphism:
  l → [ ' ^ ^ { -F(0.06)+F(0.06)+F(0.06)-|-F(0.06)+F(0.06)+F(0.06) } ]
