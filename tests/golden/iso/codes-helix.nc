(helix, spec 8.2: an end coordinate on the axis normal to the plane makes a helical move; a full turn by I J with only Z changing; G91 helix; expected: quarter turn to Z-5, full turn to Z-15, half turn by R to Z-17)
G90 G00 X20 Y10 Z0;
G03 X10 Y20 Z-5 I-10 J0 F100;
G02 X10 Y20 Z-15 I0 J-10;
G91 G02 X0 Y-20 Z-2 R10;
G90 G01 Z0;
M30;
