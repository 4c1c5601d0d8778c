diag-runtime: motion problems found by the dry run of ncc check (NC4001, NC4003-NC4005, NC4007-NC4014)
%
N1 X10 (NC4001 - G01 without F)
N2 F100
N3 G02 X0 Y10 (NC4004 - no I and no J)
N4 G03 X-10 Y0 I0 J0 (NC4005 - the centre is the start point)
N5 G03 X10 Y1 I10 (NC4003 - centre 0 0, start radius 10, end radius 10.0499)
N6 G01 X10 Y0
N7 G03 X-10 Y0 Z5 I-10 K1 (NC4007 - half a turn needs K = 5 / pi, not 1)
N8 G02 X10 Y0 Z0 I10 (NC4008 - a helix without K)
N9 G06 X20 Y5 (the intermediate point of a three-point parabola)
N10 G01 X20 Y0 (NC4009 - the motion mode changed before the end point)
N11 G33 Z-10 (NC4010 - no pitch word)
N12 G33 Z-20 K1.5 F100 (NC4011 - F in a thread block)
N13 G33 Z-30 K-1 (NC4010 - the pitch is not positive)
N14 G33 Z-40 K1.5 (NC4013 - the spindle is not turning)
N15 G34 Z-50 K1.5 (NC4012 - the profile names no pitch-change address)
N16 G93 G01 X0 Z0 (NC4014 - inverse-time feed without F in the block)
N17 G94 M30
