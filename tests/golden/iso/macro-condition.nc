(E-34: the condition of IF or WHILE must compare; AND, OR, XOR of comparisons are fine)
#1=1;
IF [#1] THEN G01 X1 F100;
IF [#1+1] GOTO 10;
IF [#1 AND 1] THEN #2=1;
WHILE [#1] DO1;
#1=0;
END1;
IF [[#1 EQ 1] AND [#1 GT 0]] THEN #2=2;
IF [#1 EQ 1 OR #1 GT 0] THEN #2=3;
WHILE [#1 LT 0 XOR #1 GT 5] DO2;
END2;
N10 M30;
