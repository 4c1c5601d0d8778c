(the manual's header: the modal state the example assumes)
G54 G90;
N1 G00 X125 Y125 Z200;
N2 G53 X100;
N3 G53 Y-100;
N4 G53 X0;
N5 G53 Y0;
N6 X0 Y0 Z50;
