(M07 M08 M09, spec 8.32 and decision 9: M07 is the same as M08, flood; all act after the rest of the block)
G90 G00 X0 Y0 Z0;
M07;
M09 G01 X10 F100;
M08 X20;
M09;
M30;
