(G28 under G41: the path leaves the offset before it, G28 moves as programmed, the next move starts up again)
G17 G90 G00 X0 Y0 Z0;
G41 D1 G01 F100 X20 Y0;
Y20;
G28 X30 Y30;
G01 X0 Y20;
X0 Y0;
G40 X-10 Y-10;
M30;
