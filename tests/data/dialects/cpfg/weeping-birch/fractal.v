angle factor: 12
initial color: 1 
color increment: 1
initial line width: 0.2 
line width increment: 0.2
viewpoint: 0,0,1
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -100000.0
back distance: 100000.0
scale factor: 0.9
z buffer: off
cue range: 0
shade mode: 1
light direction: 1.0, 1.0, 1.0
diffuse reflection: 0
tropism direction: -0.04,1.0,0.0
initial elasticity: 0.4
elasticity increment: -0.06
