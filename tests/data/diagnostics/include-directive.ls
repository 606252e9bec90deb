#include "plant.ls"
ω: F
