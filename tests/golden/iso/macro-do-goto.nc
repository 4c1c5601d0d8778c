(DO1 .. END1 without WHILE repeats for ever: a counter and a GOTO leave it)
G01 X0 Y0 Z0 F100;
#1=0;
DO1;
#1=#1+1;
IF [#1 GT 3] GOTO 100;
G01 X#1;
END1;
G01 Y99;
N100 G01 Y1;
(the same loop index used again after the first loop ended, nested in WHILE)
#2=0;
WHILE [#2 LT 2] DO2;
#2=#2+1;
#1=0;
DO1;
#1=#1+1;
G01 Z[#2*10+#1];
IF [#1 GE 2] GOTO 200;
END1;
N200 G01 Y[#2+1];
END2;
M30;
