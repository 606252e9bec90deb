/*
  kolam with straight, if joined, sides
*/
view = {position: [17,10,-3], target: [0,3,-3]};
n=2
axiom: {(0).FX+F+FX+F}(0)
p1: X --> X-F-F+FX+F+FX-F-F+FX