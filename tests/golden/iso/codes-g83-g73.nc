(G83 G73, spec 8.25 and decisions 19 23: pecks of Q from R; G83 rapids out to R after each peck and back to 0.254 above the depth reached; G73 goes back up to the depth of the pass before, R after the first; the dwell P only at the bottom; expected G83 pecks -2 -6 -10, G73 pecks -2 -6 -10)
G90 G00 X0 Y0 Z20;
G98 G83 X10 Y0 Z-10 R2 Q4 F100;
G99 X20 P0.5;
G80 G00 Z20;
G73 X30 Z-10 R2 Q4;
G80;
M30;
