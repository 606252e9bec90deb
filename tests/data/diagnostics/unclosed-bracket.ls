ω: F
F → F[+F
