#define N 2
#define LEN 1.5
#define GROW(x) F(x)
