diag-runtime-machine: problems that depend on the machine profile (NC4002, NC4006, NC4026)
%
N1 G01 X10 Y0 F100
N2 G03 X0 Y10 I-10 (a quarter circle in one quadrant - no error)
N3 G03 X0 Y-10 J-10 (NC4006 - a half circle across the boundary at X-10 Y0)
N4 S500 M03
N5 G34 Z-10 K1.5 (NC4026 - the pitch change E is missing)
N6 G34 Z-20 K1.5 E0.1 (increasing pitch - no error)
N7 G04 P1 (G04 is a member of group a)
N8 X5 (NC4002 - axis words while group a holds G04)
N9 M30
