(translate-cycle-moves-refused: ISO's cycles written as moves need the level the tool starts at: a Z from a variable leaves it not known)
#1=20
G90 G17 G00 X0 Y0 Z#1
S1000 M03
G98 G83 X10 Y0 Z-10 R2 Q4 F100
G80
M30
