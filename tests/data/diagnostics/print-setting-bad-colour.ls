colors: #7B4A2A red
ω: F
