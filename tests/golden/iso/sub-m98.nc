(M98: P1000 once, P31000 three times, P1000 L2; the subprogram O1000 stands after M30 and ends with M99)
G90 G01 X0 Y0 Z0 F100;
#100=0;
M98 P1000;
G01 Y1;
M98 P31000;
G01 Y2;
M98 P1000 L2;
G01 Y3;
(the other words of the block run before the call)
G01 Y4 M98 P1000;
(P with leading zeros: P0001000 is O1000 once, P21000 twice)
M98 P0001000;
M98 P21000;
G01 Y[#100];
M30;
O1000;
#100=#100+1;
G01 X#100;
M99;
