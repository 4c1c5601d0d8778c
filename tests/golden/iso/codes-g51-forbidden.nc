(codes forbidden under G51, spec 8.12 E-08 E-09 E-19 E-21 E-22 E-26 E-27 and decision 32: G28 G29 G52 G53 G54-G59 G92 and M06 with a new tool are NC4064; an M06 that changes nothing is ignored, decision 29, and is no error)
G90 G00 X0 Y0 Z0;
G28 X0;
G51 P2.;
G28 X0;
G29 X0;
G52 X10;
G53 X0;
G54;
G55 X0;
G92 X0;
M06;
T2 M06;
G50;
M30;
