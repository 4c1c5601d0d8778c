(G94 G95, spec 8.20: G95 feeds per revolution, F0.1 mm per turn at S1000, G94 per minute; ncc forgets F at each switch of mode, which no decision records, so G95 X40 without a new F after G94 F300 is NC4001, decision 31)
G90 G00 X0 Y0 Z0;
G01 X10 F200;
G95 S1000 M03;
G01 X20 F0.1;
G94 X30 F300;
G95 X40;
M30;
