initial line width: 0.1
line style: cylinder
viewpoint: 0,0,1
view reference point: 0,0,0
twist: 0
projection: parallel
front distance: -10000
back distance: 10000
scale factor: 0.9
z buffer: on
render mode: shaded
polygonization level: 3
tropism:  T: 0.0 1.0 0.0
tropism: T: 0.0  1.0 0.0  A:90
torque: T: 0.0 1.0 0.0
contour: 1 stripe.con
twist of cylinders: on
light: V: 400 -400 1800 
