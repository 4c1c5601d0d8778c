(cutter compensation errors, spec 8.10 and decision 32: a plane change under G41 is E-10 NC4064; start on an arc E-11, end on an arc E-13, side change on an arc E-14 are NC4066; each case is cancelled by a G40 line before the next; D0 keeps the path programmed)
G90 G00 X0 Y0 Z0;
G41 D0 G01 X10 F100;
G18;
G40 G01 X0;
G02 G41 X20 R10;
G40 G01 X0;
G41 G01 X10;
G03 X0 R5 G40;
G40 G01 X0;
G41 G01 X10;
G42 G02 X20 R5;
G40 G01 X0;
M30;
