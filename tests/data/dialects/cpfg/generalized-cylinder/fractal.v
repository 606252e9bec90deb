angle factor: 8
initial color: 1
line style: cylinder
render mode: shaded
viewpoint: 0,0,1
view reference point: 0,0,0
projection: parallel
front distance: -100
back distance: 100.0
scale factor: 0.9
z buffer: on
texture: F: squares.png E: m R: 0.5 H: l L: n
texture: F: circles.png E: m R: 1 H: l L: n
texture: F: arrow.png E: m R: 1.6 H: l L: n
texture: F: text.png E: m R: 0.7 H: l L: l
light: V:5.0 6.0 10.0 
light: V:-5.0 -6.0 -10.0 
