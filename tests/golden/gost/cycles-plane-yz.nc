Canned cycles in the YZ plane (G19): the drilling axis is X, the hole position is given by Y and Z
%
N1 G90 G19 G00 X10. Y0 Z0 S1000 M03 (INITIAL LEVEL X10)
N2 G82 X-5. Y5. Z-20. P1. R2. F100. (HOLE AT Y5 Z-20, R AT X2, BOTTOM AT X-5)
N3 Y15. (SECOND HOLE)
N4 G80 M05
N5 M30
