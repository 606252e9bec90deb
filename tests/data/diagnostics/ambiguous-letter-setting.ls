N=2
axiom: NF
N → F[+N]
