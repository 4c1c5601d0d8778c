(E-11 start on an arc, E-13 cancel on an arc, E-10 plane change, E-12 an arc smaller than the tool inside it, G51 and G68 under G41: E-17, E-24)
G17 G90 G00 X0 Y0;
G41 D1 G02 X20 Y0 R10 F100;
G01 X30;
G18;
G03 X50 Y0 R10;
G40 G02 X60 Y0 R5;
G41 D2 G01 X80;
G03 X100 Y0 R10;
G01 X120;
G51 P2.;
G68 R30.;
G40 G01 X130;
M30;
