(M98 P2001 finds O2001 in the library directory given by --lib; O2002 there has no header and calls O2001)
G90 G01 X0 Y0 Z0 F100;
#1=5;
M98 P2001;
G01 Y1;
M98 P22001;
G01 Y#1;
M98 P2002;
G01 Y#1;
M30;
