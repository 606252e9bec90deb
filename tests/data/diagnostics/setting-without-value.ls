angle:
ω: F
