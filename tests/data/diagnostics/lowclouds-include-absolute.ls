delta=22.5
#include "/etc/passwd"
axiom: F
p1: F -> FF
