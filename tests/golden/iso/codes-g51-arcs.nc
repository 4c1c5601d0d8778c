(G51 arcs under unequal factors, decision 26: an arc by R is drawn with R times the larger factor, 2 here and with -0.5 -2, mirrored twice, keeping cw; an arc by I J is scaled per axis and its end leaves the circle, E-01 NC4003; expected: centre 17.4162,-9.8324 R20; centre 14.1274,-14.1569 R20 sweep 297.95; then the error at the last arc)
G90 G00 X0 Y0 Z0;
G51 X0 Y0 I2000 J1000;
G02 X10 Y10 R10 F100;
G50;
G00 X0 Y0;
G51 X0 Y0 I-0.5 J-2.;
G02 X10 Y10 R-10;
G50;
G00 X0 Y0;
G51 X0 Y0 I2000 J1000;
G02 X10 Y10 I10;
G50;
M30;
