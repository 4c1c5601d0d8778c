(G20 in the block after a chamfer, spec 8.3 E-06 allows G20 G21 there; EXPECTED the chamfer 19,0 to 20,1 in mm, the next line ending at X0.7874 Y1 inch; ncc mixes the units of the two moves: the chamfer ends at 19.0014,0.052, off the next line)
G90 G00 X0 Y0 Z0;
G01 X20 F100 ,C1;
G20 G01 Y1;
M30;
