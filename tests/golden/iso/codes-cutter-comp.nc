(G40 G41 G42 with D, spec 8.10: D selects the radius of the profile's offsets, 1 = 5 mm, 2 = 4.25, 3 = 5, D0 radius 0; the trace shows cutter_comp events as side or D change, also in blocks without a move and in the same block as a move; the side may change on a line; the offset path itself is left to the compensation's own cases, so the moves here run with D0)
G90 G00 X0 Y0 Z0;
G41 D1;
G42;
D2;
G41 D3;
G40;
D0 G41 G01 X10 F100;
G42 Y10;
G41 D0 X20;
G40 X30;
G42 G00 Y0;
G40 G00 X0;
M30;
