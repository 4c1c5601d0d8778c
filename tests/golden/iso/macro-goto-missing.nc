(a computed GOTO to a number no block has: a run-time error at the GOTO)
N10 G01 X1 F100;
#1=10;
GOTO[#1+5];
N15 G01 X2;
#1=#1+10;
GOTO#1;
G01 X3;
M30;
