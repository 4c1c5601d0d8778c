(an ELSE without its brace at the end of the program: one message)
IF [#1 GT 1] {G01 X1 F10;} ELSE
