ω: F(atan2(1))
