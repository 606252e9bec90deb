view = {position: [45,18,5], target: [4,4,-6]};
delta=90
stemsize= 0.1
derivation length: 4
axiom: A
A -> B-F+CFC+F-D&F^D-F+&&CFC+F+B//
B -> A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//
C -> |D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//
D-> |CFB-F+B|FA&F^A&&FB-F+B|FC//