(M97 P100: an internal subprogram at block N100 after M30, ending with M99; L repeats it; P1 finds N01; M97 inside an O program)
G90 G01 X0 Y0 Z0 F100;
#1=0;
M97 P100;
G01 Y1;
M97 P100 L3;
G01 Y2;
(M97 shares the variables with the main program)
G01 Y#1;
(a second internal subprogram that calls the first one)
M97 P200;
G01 Y#1;
(leading zeros do not count: P1 and P0001 both find N01)
M97 P1;
M97 P0001;
(in O1000, M97 P5 finds O1000's own N5)
M98 P1000;
M30;
N100 #1=#1+1;
G01 X#1;
M99;
N200 G01 Z1;
M97 P100;
G01 Z2;
M99;
N01 G01 Z[#1*10];
#1=#1+1;
M99;
O1000;
M97 P5;
M99;
N5 G01 Z5;
M99;
