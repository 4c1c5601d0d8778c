(E-30: division by zero: a run-time error at the block)
G01 X1 F100;
#1=2;
#2=10/[#1-2];
G01 X2;
M30;
