Canned cycles in inches (G70): position, R, depth, peck and feed in inches, the dwell in seconds, the trace in inches
%
N1 G90 G00 X0 Y0 Z25.4 S1000 M03 (ONE INCH ABOVE THE PART, IN MM)
N2 G70 G81 X1. Y0.5 Z-0.375 R0.1 F4. (INITIAL LEVEL 1 INCH, R 0.1, BOTTOM -0.375)
N3 G83 X2.25 Q0.2 (PECKS OF 0.2 INCH FROM R, 0.2, 0.2, 0.075)
N4 G82 X3.5 P0.5 (DWELL 0.5 S, P IS NOT A LENGTH)
N5 G80 G71 M05 (BACK TO MM, THE TOOL AT Z25.4)
N6 G00 X10.
N7 M30
