(G51 negative factors, spec 8.12 and decision 26: a negative factor mirrors about the centre; one mirrored axis turns G02 into G03 and back, two do not; expected: 40,0 then ccw to 30,10 about 30,0, cw to 20,0 about 30,0; then cw to -10,-10 about -10,0)
G90 G00 X0 Y0 Z0;
G51 X50 Y0 I-1000 J1000;
G01 X60 Y0 F100;
G02 X70 Y10 R10;
G03 X80 Y0 I0 J-10;
G50;
G00 X0 Y0;
G51 X0 Y0 I-1. J-1.;
G02 X10 Y10 I10;
G50;
M30;
