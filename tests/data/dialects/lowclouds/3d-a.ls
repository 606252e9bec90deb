/* 
   TABOP Figure 1.25
   Note that we change the single quote character to the semi-colon to set the color, and use the parameterized form, ;(20), to index into the default color table.
*/ 
delta=22.5
stemsize=0.2
derivation length: 6
axiom: A
p1: A-> [&FL!A]/////;;[&FL!A]///////;;[&FL!A]
p2: F-> S/////F
p3: S -> FL
p4: L -> [;(20)^^{-f+f+f-|-f+f+f}]
