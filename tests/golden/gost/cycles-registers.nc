cycles-registers: a block without a dimension word does not run the cycle but sets its registers (decision 33)
%
N1 G90 G17 G00 X0 Y0 Z10. S500 M03
N2 G82 X10. Y0 Z-5. R2. P1. F100.
N3 P2. (no dimension word - the cycle does not run, the dwell becomes 2)
N4 X20.
N5 G80 M02
