angle increment: 30
contour: 1 /etc/hostname
