(a chamfer after a block that also retracts for M06: E-04, no chamfer is cut across the retract)
G17 G90 G00 X0 Y0 Z-5;
T2;
M06 G01 F100 X10 ,C2;
Y10;
M30;
