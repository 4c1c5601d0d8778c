(translate-frame-refused: frames a target without them cannot take: an arc under factors that differ on X and Y, an angle given by a parameter)
G90 G17 G00 X0 Y0 Z0;
G51 X0 Y0 I2. J1.;
G02 X10 Y0 R5 F100;
G50;
#1 = 30;
G68 X0 Y0 R#1;
G01 X10;
G69;
M30;
