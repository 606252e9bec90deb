ω: F
F → F[+F]]F
