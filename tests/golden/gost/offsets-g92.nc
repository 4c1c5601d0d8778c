offsets-g92: G92 sets the current coordinates of the named axes, no motion (GOST 20999 Table 5, ncc decision 17); under G91 the values add to the current coordinates
%
N1 G00 X10. Y20. Z30.
N2 G92 X0 Y0 (the current point becomes X0 Y0, Z stays 30)
N3 X5. (machine X15)
N4 G91 G92 X1. Z-5. (X5 + 1 = 6, Z30 - 5 = 25)
N5 X1. (incremental - to X7)
N6 G90 X0 Y0 Z0 (machine X9 Y20 Z5)
N7 G92 X10. (the offset is replaced, not added - machine X9 is now X10)
N8 X0 (machine X-1)
N9 M30
