roll: left
ω: F
