axiom: F(r2)
