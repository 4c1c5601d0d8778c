G89 boring, reaming (GOST 20999 Table 6): feed in, dwell at the bottom, feed out to the initial level; two holes
%
N1 G90 G00 X0 Y0 Z10. (INITIAL LEVEL Z10)
N2 G89 X10. Y20. Z-6. P0.5 R1. F80. S600 M03 (FIRST HOLE, DWELL 0.5 S)
N3 X30. (SECOND HOLE)
N4 G80 M05
N5 M30
