(a chamfer followed by a Z-only move: E-04)
G17 G90 G00 X0 Y0 Z-5;
G01 F100 X10 ,C2;
Z-6;
Y10;
M30;
