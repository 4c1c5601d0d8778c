(L given by a variable that is 0: a run-time error at the call)
G90 G01 X0 Y0 Z0 F100;
#1=0;
M98 P1000 L#1;
G01 Y1;
M30;
O1000;
G01 X1;
M99;
