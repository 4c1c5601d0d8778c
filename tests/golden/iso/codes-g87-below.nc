(G87 with the bottom Z not above R, decision 21 says NC4068; EXPECTED NC4068 at line 4 where Z-5 lies below R2; ncc runs it and bores downwards: machine_cycles.cpp takes the direction from the same comparison, so the check never fires)
G90 G00 X0 Y0 Z20;
S100 M03;
G87 X10 Z-5 R2 Q1 F100;
G80;
M30;
