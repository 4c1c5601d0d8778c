(GOTO n, GOTO#var, IF [..] GOTO, IF [..] THEN words, IF [..] THEN assignment, THEN omitted)
N10 G90 G00 X0 Y0 Z0;
(the seed's example: N12 jumps over N14 to N16)
N12 GOTO16;
N14 G00 X99;
N16 G01 X1 F100;
(a computed target; N01 is N1)
#3=20;
GOTO#3;
G00 X99;
N20 G01 X2;
#3=#3/20;
GOTO[#3];
G00 X99;
N01 G01 X3;
(a jump backwards, twice round)
#1=0;
N30 #1=#1+1;
G01 Y#1;
IF [#1 LT 2] GOTO 30;
(the seed's example: #1 LE #2 AND #2 GT 45 jumps to N40)
#1=10;
#2=50;
#3=40;
IF [#1 LE #2 AND #2 GT 45] GOTO#3;
G00 X99;
N40 G01 X4;
(a false condition goes on with the next block)
IF [#1 GT #2] GOTO 50;
G01 X5;
N50 G01 X6;
(THEN with words, THEN with an assignment, and both without THEN)
IF [#1 EQ 10] THEN G01 Z1;
IF [#1 EQ 11] THEN G01 Z99;
IF [#1 EQ 10] THEN #5=7;
IF [#1 EQ 11] THEN #5=99;
G01 Z#5;
IF [#1 EQ 10] G01 Z2;
IF [#1 EQ 11] G01 Z99;
IF [#1 EQ 10] #6=8;
IF [#1 EQ 11] #6=99;
G01 Z#6;
(IF THEN M30 ends the program only when it is true)
IF [#1 EQ 11] THEN M30;
N60 G01 X7;
IF [#1 EQ 10] THEN M30;
G00 X99;
M30;
