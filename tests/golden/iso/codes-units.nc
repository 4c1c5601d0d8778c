(G20 G21, spec 8.7 8.20 8.34.1 and decision 7: positions after G20 are in inches, the position stays where it is; F is in the units in force and keeps its number across a switch; ROUND as an address value keeps 4 decimals in G20 and 3 in G21, also inside an address expression as Fanuc's ROUND[#1]+ROUND[#2]; a variable is not rounded)
G21 G90 G00 X25.4 Y0 Z0;
G01 X50.8 F254;
G20;
G01 X1;
X2 F10;
X[ROUND[1.23456]];
#1=1.23456;
X#1;
X[ROUND[#1]+0];
G21;
G01 X25.4;
X[ROUND[1.23456]];
X#1;
M30;
