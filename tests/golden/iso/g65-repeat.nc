(G65 L repeats the macro with the same arguments; each call starts with fresh locals, and the caller's locals come back after it)
G90 G01 X0 Y0 Z0 F100;
#1=100;
#5=500;
#100=0;
(three calls, each sees A=2 and a vacant #5; the common #100 counts them)
G65 P9005 L3 A2;
(the caller's #1 and #5 are unchanged)
G01 X#1 Y#5 Z#100;
(the seed's example: L12 with A35.5 B-14.2 Q8, written with the typographic dash; the macro keeps the last values)
G65 P9006 L12 A35.5 B–14.2 Q8;
G01 X#101 Y#102 Z#117;
G01 Y#100;
M30;
O9005;
#100=#100+1;
IF [#5 EQ #0] THEN #5=0;
#5=#5+#1;
#1=#1*10;
G01 X#1 Y#5 Z#100;
M99;
O9006;
#100=#100+1;
#101=#1;
#102=#2;
#117=#17;
M99;
