width: -1
ω: F
