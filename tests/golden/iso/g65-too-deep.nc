(E-23: more than 20 nested macros: a macro calling itself without end stops with a run-time error at the 21st call)
G90 G01 X0 Y0 Z0 F100;
#100=0;
G65 P9009;
M30;
O9009;
#100=#100+1;
G01 X#100;
G65 P9009;
M99;
