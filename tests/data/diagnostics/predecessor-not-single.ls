ω: A
A B → C
