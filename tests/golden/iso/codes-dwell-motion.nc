(G04 errors, decision 8: with P, X is an axis word and G04 with a motion is NC4015, also with the motion written first; G04 without a time is NC4016; a negative time is NC4038)
G90 G00 X0 Y0 Z0;
G04 P500 X3;
G01 X10 F100 G04 P1.;
G04;
G04 P-1;
M30;
