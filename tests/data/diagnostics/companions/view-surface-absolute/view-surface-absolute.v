angle increment: 30
surface: l /etc/hostname
