(M00 M01, spec 8.28: both pause after the rest of the block, M01 as M00 whatever the optional-stop switch says, docs' difference table)
G90 G00 X0 Y0 Z0;
M00;
G01 X10 F100 M01;
M01;
X20 M00;
M30;
