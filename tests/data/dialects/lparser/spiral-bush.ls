# --- L-System Parser/Mutator --- Lj Lapre ----------------------------------
10
10
80
C
C=[cH]z!>C
H=[^^^G]%[^^^G]>>>H
G=F!^+F^+;'[&&&L]G
L=[c{--z++z++z--|--z++z++z}]
@
