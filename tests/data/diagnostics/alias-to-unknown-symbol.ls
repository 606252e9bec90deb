aliases: f=Q
ω: f
