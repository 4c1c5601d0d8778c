(G40 and a plane change in one block: the path leaves in its own plane first; then D0 offsets nothing)
G17 G90 G01 X10 Y0 F100;
G41 D1 X20;
Y10;
G40 G19;
G17;
G41 D0 G01 X0;
G40 X5;
M30;
