// missing arrow after the predecessor
ω: X
X → F[+X]F[-X]+X
F FF
