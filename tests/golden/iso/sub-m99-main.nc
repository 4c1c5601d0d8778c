(M99 in the main program, outside any call)
G90 G01 X1 Y0 Z0 F100;
M99;
G01 X2;
M30;
