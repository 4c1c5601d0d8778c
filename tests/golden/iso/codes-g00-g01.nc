(G00 G01 under G90 and G91, spec 8.1 8.18: G00 rapid, G01 at F, both modal; G91 words are increments from the position, an axis not written stays)
G90 G00 X10 Y20 Z5;
G01 X30 F200;
G91 X5 Y-5 Z-1;
G00 X1;
Y2 Z3;
G90 Y0;
G01 Z0;
X-10.5 Y-0.25;
M30;
