(arc forms, spec 8.2 A-13 A-14: end off the circle by I J is E-01 NC4003; no I J K and no R is NC4004; a full circle by R and R with a chord longer than 2R are NC4066)
G90 G00 X0 Y0 Z0;
G03 X5 Y5 I10 F100;
G02 X10 Y0;
G00 X0 Y0;
G03 X0 Y0 R10;
G02 X50 Y0 R10;
M30;
