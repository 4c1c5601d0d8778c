corpus-9.3: a program written to the standard's example format (section 9.3), read from the .fmt file
%
N5 G90 G17 T0001 (N03, N5 = 5; T04, T0001 = tool 1)
N05 G0 X-99999.999 Y99999.999 (N05 = 5 again, NC3007; G0 = G00; X, Y, 5 digits before the point, 3 after, signed)
N005 Z100 (N005 = 5 again, NC3007; Z100 without a point = 100, §3.1.4)
:10 G01 G90 G17 X12.5 Y-.03 Z1030. F150.5 S800 T1 M3 (main block; F031, 150.5; S04, 800; M3 = M03)
/N11 Z-5 F15 (block skip; F15 = 15)
N12 X0 Y0 F2 (F2 = 2)
N100 G00 Z100 M05 (N03, 100)
N999 M02 (N03, 999)
