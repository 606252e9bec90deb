module bud(x)
ω: bud(1, 2)
