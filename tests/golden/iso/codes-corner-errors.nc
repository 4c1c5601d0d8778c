(chamfer and fillet errors, spec 8.3: too large E-02, on G00 E-03, next block not a feed move E-04, G17 or M06 in the next block E-06, under G16 E-07, all NC4083, and a comment block after E-05 NC3037; EXPECTED only E-06 at lines 14-15 and 16-17, as their next blocks do make a feed move: ncc adds E-04 at lines 14 and 16)
G90 G00 X0 Y0 Z0;
G01 X20 F100 ,C25;
Y10;
G01 X0 Y0;
G00 X10 ,C1;
G01 X20 ,R1;
G00 Y10;
G01 X0 ,C1;
(a comment)
G01 Y0;
G01 X10 ,R1;
G01 Y10;
G01 X20 ,C1;
G17 G01 Y20;
G01 X30 ,C1;
T2 M06 Y30;
G16;
G01 X10 Y90 ,R1;
G01 X20 Y0;
G15;
M30;
