(G04, spec 8.4 and decisions 1 8: P2.5 is 2.5 s, P4000 is 4000 ms; X or U give the time when P is absent, also read as ms without a point; P0 is a dwell of 0; the dwell comes after the rest of the block; with X and U both, X is taken and U warned as unused)
G90 G00 X0 Y0 Z0;
G04 P2.5;
G04 P4000;
G04 X1.5;
G04 X1500;
G04 U2.;
G04 U250;
G04 P0;
G04 P1 S500 M03;
G04 P1. M08;
G04 U0.5 M05;
G04 X2 U3;
M30;
