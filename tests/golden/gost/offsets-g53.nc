offsets-g53: G53 acts in its block only - its dimension words are machine coordinates; the preset offset stays in force (GOST 20999 Table 5, ncc decision 16); trace positions stay in the active system
%
N1 G54 G00 X10. Y10. Z0 (machine X110 Y60 Z-20)
N2 G53 X0 Y0 Z0 (machine zero = X-100 Y-50 Z20 in system 1)
N3 X5. (G54 still in force)
N4 M30
