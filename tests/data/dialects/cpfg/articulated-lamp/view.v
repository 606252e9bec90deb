viewpoint: 0,0.1,10
view reference point: 0.5,1,0
projection: perspective
scale factor: 2.0
// viewpoint: 0,0.01,1
// view reference point: 0,0,0
// projection: parallel
// scale factor: 0.9
front distance: -100.0
back distance: 100.0
line style: cylinder
render mode: shadows
polygonization level: 4
light direction: 1.0, 1.0, 1.0

