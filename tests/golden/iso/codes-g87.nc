(G87, spec 8.27 and decisions 21 22: oriented stop, rapid shift Q, rapid to R below the part, shift back at feed, spindle cw, feed up to Z, dwell, oriented stop, rapid shift, feed out to the initial level under G98 and G99 alike, shift back, restart)
G90 G00 X0 Y0 Z20;
S800 M03;
G98 G87 X10 Y0 Z-5 R-20 Q2 P0.5 F100;
G99 X20;
G80;
M30;
