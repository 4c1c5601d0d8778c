(G81 G82 with G98 G99, spec 8.21 8.23 8.24: rapid to the hole at the initial level, rapid to R, feed to Z, G82 dwells P, P500 is 0.5 s and P1.5 1.5 s, rapid back to the initial level under G98 or to R under G99; G99 stays in force into the G82 holes)
G90 G00 X0 Y0 Z50;
G98 G81 X10 Y10 Z-5 R2 F100;
X20;
G99 Y20;
G80;
G00 Z20;
G82 X40 Y0 Z-3 R5 P500;
G99 X50 P1.5;
G80 G00 X0 Y0;
M30;
