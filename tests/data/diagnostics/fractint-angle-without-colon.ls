Angle 6
Axiom F
F=F+F--F+F
