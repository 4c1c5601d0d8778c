(M98 P2000 in the library: O2000.nc starts with a comment line and then its O2000 header)
G90 G01 X0 Y0 Z0 F100;
#1=5;
M98 P2000;
G01 Y#1;
M30;
