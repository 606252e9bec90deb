ω: F
F → FF /* unfinished
