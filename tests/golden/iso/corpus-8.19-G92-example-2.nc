(the manual's header: the modal state the example assumes)
G55 G90;
N1 G00 X0 Y0 Z100 G92 Y-100;
N2 G01 X70 Y50 G92 Y150;
N3 G00 X0 Y0 Z100;
