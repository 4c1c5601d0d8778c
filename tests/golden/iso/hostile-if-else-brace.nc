(hostile: a multi-line IF whose ELSE has no brace crashed the lowering)
IF [#1 GT 1] {G01 X1;} ELSE
G01 X2 F100
M30
