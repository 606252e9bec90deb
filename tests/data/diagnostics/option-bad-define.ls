#define r2 0.6
axiom: F(r2)
