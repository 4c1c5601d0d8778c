(cycle words kept, decision 18: R Z Q P F stay while a cycle is active, also into another cycle code; a block with an axis word or R drills, one with only M or F does not; a start above R keeps its level; G80 forgets the words, so G81 without R is NC4018 at the last block)
G90 G00 X0 Y0 Z20;
G99 G83 X10 Z-6 R2 Q3 P0.2 F100;
X20;
M08;
F200;
R1;
Z-3;
G73 X30;
G80 X40;
G81 X50 Z-1;
M30;
