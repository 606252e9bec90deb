axiom: F(0)
