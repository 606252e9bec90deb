n=12, δ=90°
A
A → B-F+CFC+F-D&F^D-F+&&CFC+F+B//
B → A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//
C → |D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//
D → |CFB-F+B|FA&F^A&&FB-F+B|FC//
