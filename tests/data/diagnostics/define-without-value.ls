#define a
ω: F
