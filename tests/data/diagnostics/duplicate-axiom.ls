ω: F
axiom: G
