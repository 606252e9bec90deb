n=1
axiom: F
F -> F]]0;pwned[2J
