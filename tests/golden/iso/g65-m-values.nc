(G65: M is argument #13; its value may be any number, as for the other letters: 2.5, -13, 1000)
G90 G01 X0 Y0 Z0 F100;
G65 P9002 A2.5 M2.5;
G65 P9002 A-13 M-13;
G65 P9002 A1000 M1000;
M30;
O9002;
G01 X#13 Y#1;
M99;
