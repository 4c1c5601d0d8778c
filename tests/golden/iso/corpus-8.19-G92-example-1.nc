(the manual's header: the modal state the example assumes)
G54 G90;
N1 G00 X150 Y50 Z200;
N2 G92 X0 Y0 Z0;
N3 G01 X100;
N4 G92 X250 Y50 Z200;
