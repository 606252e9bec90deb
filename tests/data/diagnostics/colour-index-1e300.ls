axiom: F'(1e300)F
