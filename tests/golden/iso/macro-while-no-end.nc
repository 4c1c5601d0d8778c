(WHILE .. DO2 without its END2: an error, not a crash)
#1=0;
WHILE [#1 GT 1] DO2;
G01 X1 F100;
M30;
