width scale: 1e10
axiom: !(1e300)F
