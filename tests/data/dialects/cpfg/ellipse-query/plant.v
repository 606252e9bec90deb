angle factor: 6
initial color: 127
color increment: 1
initial line width: 3 pixels
line width increment: 0.5
viewpoint: 0,0,300
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -100000.0
back distance: 100000.0
scale factor: 0.80
z buffer: on
cue range: 0
shade mode: 1
light direction: 0.0,1.0,0.0
diffuse reflection: 100
tropism direction: 1.0,0.0,0.0
initial elasticity: 0.00
elasticity increment: 0.0
surface ambient: .50
surface diffuse: 0.50
