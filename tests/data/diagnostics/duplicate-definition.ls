#define a 45 /* branching angle */
#define a 30
ω: +(a)F
