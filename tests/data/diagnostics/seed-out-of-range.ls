seed: -1
ω: F
