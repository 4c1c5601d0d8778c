(G20 in the block after a fillet, spec 8.3 E-06 allows it; EXPECTED a fillet R1 about 19,1 mm; ncc reports E-02 NC4083 as it measures the next line in inches)
G90 G00 X0 Y0 Z0;
G01 X20 F100 ,R1;
G20 G01 Y1;
M30;
