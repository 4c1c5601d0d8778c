(E-31: TAN of 90: a run-time error at the block)
G01 X1 F100;
#1=2;
#2=TAN[#1*45];
G01 X2;
M30;
