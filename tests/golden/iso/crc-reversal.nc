(a path that turns back on itself under G41: the arc around the end goes clockwise, outside)
G17 G90 G00 X30 Y0 Z0;
G41 D1 G01 X20 Y0 F100;
X0;
X20;
G40 X30 Y0;
M30;
