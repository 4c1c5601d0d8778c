(E-15, spec 8.11: the length offset changing during circular interpolation with a Z motion is an error; EXPECTED an error at the helix blocks with H1, G49 and G44; ncc runs them and changes the offset on the helix)
G90 G00 X10 Y0 Z10;
G43 H2 Z5;
G02 X20 R5 Z-1 H1 F100;
G49 G03 X10 R5 Z-2;
G44 H2 G02 X20 R5 Z-3;
M30;
