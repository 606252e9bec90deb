colour: 1048576
axiom: F'F
