(M03 M04 M05 with S, spec 8.30 and decision 9: M03 M04 start the spindle before the motion of their block, M05 stops it after; S alone changes the speed; M03 without any S runs, A-38)
G90 G00 X0 Y0 Z0;
M03;
S1000 M03 G01 X10 F100;
M04;
S1500;
M05 G01 X20;
S800 M04 X30;
M05;
M30;
