(G92, spec 8.19 and decision 28: the position takes the values given, without motion; only the axes written change; with axis words before G92 the move is made first and the words after G92 are its values; under G91 ncc reads the values as increments of the position, which neither spec nor decisions say; M30 clears it; expected offsets 150,50,200 then 150,40,200 then 160,50,200 then 155,50,200)
G90 G00 X150 Y50 Z200;
G92 X0 Y0 Z0;
G01 X100 F100;
G92 Y10;
G00 X0 Y0 Z0;
G00 X10 Y10 G92 X0 Y0;
G00 X5 Y5;
G91 G92 X0;
G92 X5;
G90 G00 X0 Y0;
M30;
