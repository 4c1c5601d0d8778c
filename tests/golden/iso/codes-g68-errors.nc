(G68 errors, spec 8.17 E-24 and decisions 27 32: G68 with a motion, F or M is NC3037, G17 G90 may share it; G68 under G41 is NC4064, also when rotation is already on)
G90 G00 X0 Y0 Z0;
G68 R30. G01 X10 F100;
G68 R30. M08;
G17 G90 G68 R30.;
G69;
G41 D1 G01 X10 F100;
G68 R30.;
G40 G01 X0;
G68 R30.;
G41 D1 G01 X10;
G68 R60.;
G40 G01 X0;
G69;
M30;
