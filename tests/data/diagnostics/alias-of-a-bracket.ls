aliases: [=F
ω: F
