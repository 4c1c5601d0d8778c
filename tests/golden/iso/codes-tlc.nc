(G43 G44 G49 with H, spec 8.11 and decision 30: G43 adds and G44 subtracts the H length, H1 75 H2 110 H3 95; G43 without H takes the last H; a new H replaces the offset, H0 and G49 cancel; an XY move after G43 keeps its Z; M30 ends the offset; the canon variant prints the offset before the XY move of line 4 with Z100, which in LinuxCNC's reading lifts Z by 75, the tlo_xy_first difference)
G90 G00 X0 Y0 Z100;
G43 H1;
X10;
Z50;
G44 H2 Z40;
G49 Z30;
G43 Z20;
H3 Z10;
H0 Z5;
G43 H2 G91 Z-1;
G90 G02 X20 R5 Z0 F100;
M30;
