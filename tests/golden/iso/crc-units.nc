(G20 and G55 and G50 under compensation are refused: the offset path would mix units or frames)
G17 G90 G21 G00 X0 Y0 Z0;
G41 D1 G01 F100 X20 Y0;
G20 Y1.;
X0;
G40 X-1. Y-1.;
M30;
