(program numbers with fewer than 4 digits: O1 is O0001, and M98 P1, G65 P0001 and M98 P20001 all call it)
G90 G01 X0 Y0 Z0 F100;
M98 P1;
G65 P0001 A5;
M98 P20001;
M30;
O1;
G01 X[#1+1];
M99;
