(the manual's header: the modal state the example assumes)
G54;
N1 G00 X50 Y50 Z50;
N2 G52 X100 Y100;
N3 G01 X0 Y0;
N4 G02 X100 R50;
N5 G52 X0 Y0;
