parabola-3d: a parabola in a plane of space that is none of the coordinate planes (GOST 20999 §4.4.1), both forms, G90 and G91
%
N1 G90 G00 X0 Y0 Z0 (P0 0 0 0)
N2 G06 X4. Y2. Z3. F100. (intermediate point P1 4 2 3)
N3 X10. Y0 Z4. (end point P2 10 0 4, control 2 P1 - P0/2 - P2/2 = 3 4 4)
N4 G00 X0 Y0 Z0
N5 G06 X10. Y0 Z4. I3. J4. K4. (the same curve in one block)
N6 G00 X0 Y0 Z0
N7 G91 G06 X4. Y2. Z3. (G91, P1 - P0)
N8 X6. Y-2. Z1. (G91, P2 - P1)
N9 M02
