// Tree A of seed 001 ("Modeling a Tree using L-System", 2008), written with
// the blog's own symbols and setting names, plus an alias block.
// The blog: f creates a branch, l a leaf, +/- rotate, ^/v pitch up/down,
// </> twist left/right. Its radius shrinks by 0.0015 per generation.
// The blog calls + "right"; lsolid's + turns left, so the tree comes out
// mirrored, which a symmetric tree does not show.
// test: n = 3 (the full model, n = 6, is built by 'make gallery', not in CI)
// expect: segments 369, polygons 728
// volume: 2987.4 mm³ as the test builds it (within 1%)
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
Angle : 25
Iterations: 6
Branch radius: 0.02
Branch radius reduction: 0.0015
Branch length (height): 0.15
Initial value : fffffA
Production rules : A = f[++Al][--Al]>>>A
// The blog does not print its leaf; this one is ABOP's (fig. 1.25).
homomorphism:
  l → [ ' ^ ^ { -F(0.06)+F(0.06)+F(0.06)-|-F(0.06)+F(0.06)+F(0.06) } ]
