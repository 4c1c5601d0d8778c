(a chamfer in the M30 block: E-04)
G17 G90 G00 X0 Y0 Z0;
M30 G01 F100 X10 ,C2;
