ω: F{-f+f+f-|-f+f+f}
σ=30
width: 0.2
