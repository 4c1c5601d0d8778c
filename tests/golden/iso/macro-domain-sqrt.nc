(E-31: SQRT of a negative value: a run-time error at the block)
G01 X1 F100;
#1=2;
#2=SQRT[#1-3];
G01 X2;
M30;
