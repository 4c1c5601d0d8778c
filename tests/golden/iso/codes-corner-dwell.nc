(G04 after a chamfer, spec 8.3 E-06 allows G04 in the next block, which must also make a feed move E-04, and decision 8 makes G04 with a motion NC4015: a G04 block alone is E-04, with a move NC4015, so no program can use the allowance)
G90 G00 X0 Y0 Z0;
G01 X20 F100 ,C1;
G04 P1.;
G01 X30 ,C1;
G01 Y10 G04 P1.;
M30;
