# --- L-System Parser/Mutator ---
4       # recursion
20      # angle
10      # thickness
F
F=F[+F]F
@
