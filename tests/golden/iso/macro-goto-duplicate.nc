(a block number used twice: GOTO 10 from before both; the manual does not say which one it finds [A-46])
G01 X0 Y0 Z0 F100;
GOTO 10;
G01 X9;
N10 G01 X1;
N10 G01 Y2;
M30;
