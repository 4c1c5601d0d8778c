(a full circle under G42 followed by an inside corner: the offset circle ends at the intersection)
G17 G90 G00 X0 Y-10 Z0;
G42 D1 G01 X10 Y0 F100;
G03 I10;
G01 X0 Y10;
G40 X0 Y30;
M30;
