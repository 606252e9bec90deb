n=3
angel: 25.7
F
F → F[+F]F[-F]F
