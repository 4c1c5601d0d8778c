(GOTO errors found before the run: a literal target no block has, a target that is not a block number, a jump into another program)
N10 G01 X1 F100;
GOTO 11;
GOTO 1.5;
GOTO -3;
IF [#1 EQ #0] GOTO 123456;
M98 P1000;
M30;
O1000;
N20 GOTO 10;
M99;
