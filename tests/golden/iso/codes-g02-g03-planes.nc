(G02 G03 in G18 with I K and G19 with J K, and R, spec 8.2 8.5: G18 arcs lie in Z-X, G19 in Y-Z, the other axis makes a helix; expected: G18 centres Z0 X10 then Z0 X30, G19 centres Y5 Z10 then Y10 Z0)
G90 G00 X0 Y0 Z0;
G18 G02 X10 Z10 I10 K0 F100;
G03 X20 Z0 I0 K-10;
G02 X40 R10;
G02 X20 Y5 R-10;
G19 G02 Y15 Z10 J0 K10;
G03 Y5 Z0 J-10 K0;
G02 Y15 R5;
G03 Y5 X25 R5;
G17 G02 X30 Y5 Z3 I2.5 J0;
M30;
