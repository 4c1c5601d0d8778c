(E-31: ACOS of -1.5 is outside [-1, 1]: a run-time error at the block)
G01 X1 F100;
#1=2;
#2=ACOS[-1.5];
G01 X2;
M30;
