(G41 around a square counter-clockwise: the tool inside; start-up along the first move to beside the second one's start; inside corners at the offset lines' intersections; G40 with a move leaves from beside the last end)
G17 G90 G00 X0 Y0 Z0;
G41 D1 G01 X20 Y0 F100;
Y20;
X0;
Y0;
G40 X-10 Y-10;
M30;
