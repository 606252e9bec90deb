base: tripod
ω: F
