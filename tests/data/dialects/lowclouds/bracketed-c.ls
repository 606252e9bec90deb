n=1; delta=22.5; stemsize=0.1
derivation length: 4
axiom: F
p0: F->FF-[-F+F+F]+[+F-F-F]

