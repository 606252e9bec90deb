tropism: 0, -1
ω: F
