n=1
ω: A(0)
A(x) → B : x
