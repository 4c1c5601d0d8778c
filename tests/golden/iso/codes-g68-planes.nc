(G68 in G18 and with G51, decision 24: the rotation is in the active plane, in G18 from +Z towards +X; with scaling on, the centre is scaled as the path is; expected: X0 Z-10; centre 20,0 after scaling, point 40,0 turned to 20,20)
G90 G00 X0 Y0 Z0;
G18 G68 X0 Z0 R90.;
G01 X10 Z0 F100;
G69 G17;
G00 X0 Y0 Z0;
G51 X0 Y0 P2.;
G68 X10 Y0 R90.;
G01 X20 Y0;
G69;
G50;
M30;
