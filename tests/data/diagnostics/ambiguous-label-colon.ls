#define t 2
axiom: A
A : t > 1 → B
