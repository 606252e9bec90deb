axiom: F(1e300)
