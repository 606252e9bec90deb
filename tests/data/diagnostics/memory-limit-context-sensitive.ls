ω: A(1)
n=40
A(x) : x > 0 → A(x)A(x)
F < F → F
