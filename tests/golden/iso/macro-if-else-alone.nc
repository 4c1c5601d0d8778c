(ELSE and ELIF without an IF before them: an error, not a crash)
G01 X1 F100;
ELSE {G01 X2;}
ELIF [#1 EQ 1] {G01 X3;}
M30;
