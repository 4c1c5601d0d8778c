(cycle errors, spec 8.23-8.27: no R is NC4018, no Z NC4017, no Q for G83 G73 G76 G87 NC4029, Q0 NC4024; each cycle is cancelled by G80 before the next)
G90 G00 X0 Y0 Z20;
G81 X10 Z-5 F100;
G80;
G81 X10 R2;
G80;
G83 X10 Z-5 R2;
G80;
G73 X10 Z-5 R2;
G80;
G76 X10 Z-5 R2;
G80;
S100 M03;
G87 X10 Z5 R-20;
G80;
G83 X10 Z-5 R2 Q0;
G80;
M30;
