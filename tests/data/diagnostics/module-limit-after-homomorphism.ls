n=0
ω: A
homomorphism:
maximum depth: 1000
A → AA
