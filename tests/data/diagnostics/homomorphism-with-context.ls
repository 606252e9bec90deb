ω: AB
homomorphism:
A < B → F
