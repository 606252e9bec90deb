angle increment: 30
contour: 1 sub
