(syntax errors in Macro B blocks: each block reports its first error, the other blocks are still read)
#1=;
#1==2;
#=3;
#1=2+*3;
G01 X#1 F;
IF #1 GT 2 GOTO 10;
IF [#1 GT 2] GOTO;
GOTO;
#1=SIN 30;
#1=FOO[1];
#1=2 #3;
WHILE [#1 GT 2] DO;
END;
#1=2 $ 3;
(E-34: IF and WHILE stand at the start of the block; THEN does not take GOTO)
G01 X1 F100 IF [#1 EQ 1] GOTO 10;
X1 WHILE [#1 EQ 1] DO1;
IF [#1 EQ 1] THEN GOTO 10;
G01 X1 Y2 Z3 F100;
N10 M30;
