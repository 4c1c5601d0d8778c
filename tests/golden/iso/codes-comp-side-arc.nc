(E-14 at run time, spec 8.10: a side change G41 to G42 on an arc is NC4066 at the block; the trace already shows cutter_comp right before the error, expected no event of the refused block; D0 keeps the path programmed)
G90 G00 X0 Y0 Z0;
G41 D0 G01 X10 F100;
G02 X20 R5 G42;
G40 G01 X0;
M30;
