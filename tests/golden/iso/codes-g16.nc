(G15 G16 in G17, spec 8.6 and decision 25: X is the radius, Y the angle in degrees from +X; G90 about the work zero, a word not written keeps the position's radius or angle; G91 about the position with radius and angle as written, a word not written is 0; expected: 43.3013,25 then 25,43.3013 then 50,86.6025 then 0,-100 then 10,-100 then 10,-90 then no move)
G90 G00 X0 Y0 Z0;
G17 G90 G16;
G01 X50 Y30 F100;
Y60;
X100;
Y-90 Z-5;
G91 X10 Y0;
X10 Y90;
Y45;
G90 G15 X0 Y0;
M30;
