#define LEAF 1
