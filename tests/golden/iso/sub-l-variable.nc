(L given by a variable: 2 calls; L above 999 must be refused as when written as a number [E-28])
G90 G01 X0 Y0 Z0 F100;
#100=0;
#1=2;
M98 P1000 L#1;
G01 Y#100;
#1=1000;
M98 P1000 L#1;
G01 Y#100;
M30;
O1000;
#100=#100+1;
M99;
