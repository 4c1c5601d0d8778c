(G51 errors, spec 8.12 and decisions 26 27 32: G51 with a motion, F or M in its block is E-16 NC3037, G90 G91 G17 may share it; no factor and a factor 0 are NC4057; G51 under G41 is E-17 and under G68 E-18, both NC4064)
G90 G00 X0 Y0 Z0;
G51 X0 Y0 P2. G01 X10 F100;
G51 P2. M08;
G17 G91 G51 P2.;
G50 G90;
G51 X0 Y0;
G51 P0;
G41 D1 G01 X10;
G51 P2.;
G40 G01 X0;
G68 R30.;
G51 P2.;
G69;
M30;
