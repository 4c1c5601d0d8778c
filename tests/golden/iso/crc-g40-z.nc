(G40 in a block of its own, then a retract in Z: the right-angle exit comes first, at the contour's height)
G17 G90 G00 X0 Y0 Z0;
G41 D1 G01 F100 X20 Y0;
Y20;
G40;
G00 Z10;
X-10 Y-10;
M30;
