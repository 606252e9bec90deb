wall: 0.8mm
wall: 2mm
ω: F
