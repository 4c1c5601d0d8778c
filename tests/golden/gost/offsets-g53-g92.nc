offsets-g53-g92: G53 ignores the G92 offset too in its block; the G92 offset stays in force (GOST 20999 Table 5, ncc decisions 16-17); trace positions stay in the active system
%
N1 G00 X10. Y20. Z30.
N2 G92 X0 Y0 Z0 (offset X10 Y20 Z30)
N3 G53 X0 Y0 Z0 (machine zero = X-10 Y-20 Z-30 in the G92 system)
N4 X5. (the G92 offset still in force - machine X15)
N5 M30
