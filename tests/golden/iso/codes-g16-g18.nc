(G16 in G18 and G19, spec 8.6: G18 radius Z and angle X from +Z, G19 radius Y and angle Z from +Y; the third axis is a plain coordinate; expected: X20 Z0, then X10 Z17.3205, then in G19 Y7.0711 Z7.0711 with X kept)
G90 G00 X0 Y0 Z0;
G18 G16;
G01 Z20 X90 Y7 F100;
X30;
G19;
Y10 Z45;
G17 G15;
X1 Y2;
M30;
