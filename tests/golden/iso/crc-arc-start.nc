(G41 in a block of its own, then an arc: E-11)
G17 G90 G00 X0 Y0 Z0;
G41 D1;
G02 X20 Y0 R10 F100;
G01 X30;
G40;
X40;
M30;
