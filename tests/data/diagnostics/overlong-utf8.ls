axiom: FÀ¯F
