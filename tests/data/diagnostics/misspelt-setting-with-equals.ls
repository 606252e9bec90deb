anlge=90, n=2
ω: F
