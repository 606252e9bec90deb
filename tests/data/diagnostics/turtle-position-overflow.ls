axiom: F(1e308)F(1e308)
