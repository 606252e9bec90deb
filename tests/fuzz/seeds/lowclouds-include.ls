delta=22.5
#include "tests/fuzz/seeds/params.h"
axiom: A
p1: A -> GROW(LEN)[+A][-A]
