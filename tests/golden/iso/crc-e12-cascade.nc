(one cause, one message: the arc after an E-12 is no start-up on an arc, E-11; decision 74)
G17 G90 G00 X0 Y0;
G41 D2 G01 X80 F100;
G03 X100 Y0 R10;
G02 X120 Y0 R10;
G01 X140;
G40 G01 X150;
M30;
