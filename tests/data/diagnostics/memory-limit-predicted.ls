ω: A
n=30
A → AA
B < C → D
