#defne a 2
ω: F
