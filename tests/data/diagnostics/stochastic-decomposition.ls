ω: A
decomposition:
A -(0.5)→ F
