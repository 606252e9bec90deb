ω: F(foo(1))
