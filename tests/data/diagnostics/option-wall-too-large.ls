axiom: F
