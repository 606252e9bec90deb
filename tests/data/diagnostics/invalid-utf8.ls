axiom: Fÿ[F
F -> F
