(a computed GOTO whose value is not a whole number: a run-time error at the GOTO)
N15 G01 X1 F100;
#1=15.4;
GOTO#1;
G01 X2;
M30;
