// Tree C of seed 001 ("Modeling a Tree using L-System", 2008), with the
// blog's own symbols and setting names, plus an alias block.
// test: n = 7 (the full model, n = 13, is built by 'make gallery', not in CI)
// expect: segments 2186, polygons 0
// volume: 8088.9 mm³ as the test builds it (within 1%)
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
Angle : 15
Iterations: 13
Branch radius: 0.02
Branch radius reduction: 0.0015
Branch length (height): 0.15
Initial value : fA
Production rules : A = ^fB>>>B>>>>>B, B = [^^f>>>>>>A]
