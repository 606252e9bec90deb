# --- L-System Parser/Mutator --- Lj Lapre ----------------------------------
10
10
50
p
p=FF[cag]>(120)[cag]>(120)[cag]>(50)!(0.9)'~(3)p
g=~(3)!'F[cmb][cnb]^(5)g
b=~(3)!'F[cmF][cnF]^(3)b
a=&a
m=+m
n=-n
@
