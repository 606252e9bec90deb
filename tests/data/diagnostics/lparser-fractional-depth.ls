# --- L-System Parser/Mutator ---
2.5     # recursion: Lparser grows the last step by half
20      # angle
10      # thickness
F
F=F[+F]F
@
