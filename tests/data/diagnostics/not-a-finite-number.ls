ω: F(sqrt(-1))
