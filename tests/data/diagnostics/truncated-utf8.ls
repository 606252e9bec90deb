axiom: FÃ
