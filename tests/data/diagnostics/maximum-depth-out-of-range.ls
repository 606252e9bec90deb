maximum depth: 1001
ω: F
