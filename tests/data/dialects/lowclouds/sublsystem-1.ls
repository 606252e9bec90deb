lsystem: 1
ignore: $
dlength: 
axiom: A
p11: A --> I[$(2)A$]
endlsystem

lsystem: 2
ignore: $
axiom: A
P21: A -> IA
endlsystem
