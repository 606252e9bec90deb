#define r1 0.9
ω: A(1)
A(l) → F(l)A(l*r2)
