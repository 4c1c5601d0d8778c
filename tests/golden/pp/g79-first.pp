%13 "a subprogram written before the main part"
N1 G79 L5
N2 G91 X1
N3 G70
N4 G71 L5
N5 M30
