(M98 errors: a count in P and L together, no P, L above 999, L0, a program that does not exist, a subprogram without M99)
M98 P31000 L2;
M98 L2;
M98 P1000 L1000;
M98 P1000 L0;
M98 P1000 L999;
M98 P1001;
M98 P1239;
M30;
O1000;
G01 X1 F100;
M99;
O1001;
G01 X2 F100;
