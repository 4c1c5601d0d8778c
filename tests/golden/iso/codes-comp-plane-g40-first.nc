(G40 then a plane code in one block under G41, spec 1.8: word order is free; ncc accepts G40 G19 but prints the plane before cutter_comp off; codes-comp-plane-g40-last writes G19 G40, which ncc rejects: EXPECTED one answer for both orders, both accepted as G40 ends compensation in the block, or both E-10 NC4064; D0 keeps the path programmed)
G90 G00 X0 Y0 Z0;
G41 D0 G01 X10 F100;
G40 G19;
G17 G01 Y10;
M30;
