(G76, spec 8.27 and decision 22: feed to Z, dwell P, oriented stop, shift Q along +X at feed, rapid out to the initial level or R, shift back and restart the spindle)
G90 G00 X0 Y0 Z20;
S800 M03;
G98 G76 X10 Y0 Z-10 R2 Q1 P0.5 F100;
G99 X20;
G80 G00 Z20;
M30;
