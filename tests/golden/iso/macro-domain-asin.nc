(E-31: ASIN of 2 is outside [-1, 1]: a run-time error at the block)
G01 X1 F100;
#1=2;
G01 Y[ASIN[#1]];
G01 X2;
M30;
