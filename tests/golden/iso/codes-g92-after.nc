(G92 before a motion, spec 8.19 E-25 and decision 28: a motion code after G92 is NC3037, and an axis word given twice NC3001; an axis word after G92 with no code is a G92 value)
G90 G00 X0 Y0 Z0;
G92 X0 G00 X1;
G92 Y5 G01 X2 F100;
G00 X1 G92 Y0 X3;
M30;
