ω: A[B]C
[A] < B → C
