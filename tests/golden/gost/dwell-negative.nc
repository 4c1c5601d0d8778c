dwell-negative: a dwell time must not be negative (NC4038), in G04 and in the dwell of a canned cycle (GOST 20999 Table 5, Table 6)
%
N1 G90 G00 X0 Y0 Z10. S500 M03
N2 G04 P-1. (NC4038)
N3 G82 X10. Y10. Z-5. R2. P-0.5 F100. (NC4038)
N4 G80 M02
