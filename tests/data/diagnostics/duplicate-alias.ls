aliases: f=F f=G
ω: f
