(E-01, spec 8.2 and profile arc_tolerance 0.01 mm: start and end radius differing by 0.009 runs, by 0.02 is NC4003 at the block)
G90 G00 X0 Y0 Z0;
G02 X20.009 Y0 I10 J0 F100;
G02 X0.02 Y0 I-10.0045 J0;
G01 X0;
M30;
