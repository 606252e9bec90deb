wall: 3ft
ω: F
