n=3
axiom: A
A → AB
B → A
