axiom: A{f}
