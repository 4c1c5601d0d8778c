(M06 under G41 ends the compensation: a right-angle exit at the height of the contour, then the retract)
G17 G90 G00 X0 Y0 Z-5;
G41 D1 G01 F100 X20 Y0;
Y20;
T2 M06;
G00 X50 Y50;
M30;
