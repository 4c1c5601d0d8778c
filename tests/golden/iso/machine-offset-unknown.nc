(decision 62: a tool, offset or work offset the machine lacks names --machine and what it has; the built-in fanuc has offsets 1-400, G54-G59 and G54.1 P1-P48)
G90 G00 X0 Y0 Z10;
T401;
G43 H401 Z5;
G10 L20 P49 X0;
G10 L12 P2 R-1.;
M30;
