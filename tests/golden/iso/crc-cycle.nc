(G81 under G41: the holes are drilled where programmed, the contour starts up again after G80)
G17 G90 G00 X0 Y0 Z10;
G41 D1 G01 F100 X20 Y0;
Y20;
G81 X30 Y30 Z-5 R2;
X40;
G80;
G01 X0 Y20;
X0 Y0;
G40 X-10 Y-10;
M30;
