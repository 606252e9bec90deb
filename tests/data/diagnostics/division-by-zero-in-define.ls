#define a 1/0
ω: F(a)
