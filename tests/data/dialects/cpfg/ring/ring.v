initial line width: 1
line style: polygon

viewpoint: 0,0,1
view reference point: 0,0,0
front distance: -100000.0
back distance: 100000.0
projection: parallel
scale factor: 0.9
z buffer: off

shade mode: 1
light direction: 1.0, 1.0, 1.0
line style: polygon
