n=2
F → FF
