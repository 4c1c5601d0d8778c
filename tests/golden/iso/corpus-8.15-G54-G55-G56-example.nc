(the manual's header: the modal state the example assumes)
G54;
N1 G90 G55 G00 X0 Y0 Z20;
N2 G02 G91 Y100 R-60;
N3 G90 G56 G00 X150 Y250 Z0;
N4 G54;
N5 G00 X0 Y0 Z0;
