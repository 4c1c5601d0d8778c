(E-31: LN of 0: a run-time error at the block)
G01 X1 F100;
#1=2;
#2=LN[#1-2];
G01 X2;
M30;
