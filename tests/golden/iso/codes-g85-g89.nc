(G85 G86 G88 G89, spec 8.27: G85 feeds out to R; G86 stops the spindle at the bottom, rapids out, restarts; G88 runs as G86 with the dwell P; G89 as G85 with the dwell; under G98 a rapid from R to the initial level follows)
G90 G00 X0 Y0 Z20;
S800 M03;
G98 G85 X30 Y0 Z-10 R2 F100;
G99 X40;
G80 G00 Z20;
G98 G86 X50 Z-10 R2;
G99 X60;
G80 G00 Z20;
G98 G88 X70 Z-10 R2 P1.;
G99 X80;
G80 G00 Z20;
G98 G89 X90 Z-10 R2 P1.;
G99 X100;
G80 G00 Z20;
M30;
