(G53, spec 8.14: one-shot moves in machine coordinates, G54 origin at machine -125,-125,0; linear and circular moves; the next block is in G54 again; G53 without words moves nothing; expected G54 positions 125,125 then 200,125 then 135,135,-10 then arcs about 5,135)
G90 G00 X100 Y50 Z200;
G53 G01 X0 Y0 F100;
G01 X200;
G53 X10 Y10 Z-10;
G00 X0;
G53 G02 X-115 Y10 R5;
G53 G03 X-125 I-5;
G00 G53;
X1;
M30;
