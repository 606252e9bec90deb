# A width no printer can meet beside a drawing two steps long.
n=0
axiom: F!(1e200)F
