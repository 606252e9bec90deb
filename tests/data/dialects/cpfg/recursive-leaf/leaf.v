angle increment: 45 
initial line width: 2 pixels
initial color: 1
color increment: 1
scale factor: 0.9000


