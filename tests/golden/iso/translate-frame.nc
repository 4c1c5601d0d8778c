(translate-frame: G68 and G51 into a target without them, written into the points; expected: 10,10 Z0; 5,10; ccw to 0,5 about 5,5; mirrored X, the cw arc turned ccw to -10,5 about -5,5; after G50 cw to 0,5 about -5,5, G02 written again)
G90 G17 G00 X0 Y0 Z5;
G68 X10 Y0 R90.;
G01 X20 Y0 Z0 F200;
G91 Y5;
G90 G03 X15 Y10 R5;
G69;
G51 X0 Y0 I-1. J1.;
G02 X10 Y5 I5 J0;
G50;
G02 X0 Y5 I5 J0;
M30;
