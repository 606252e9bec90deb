ω: F
 → FF
