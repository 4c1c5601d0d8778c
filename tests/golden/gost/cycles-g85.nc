G85 boring, reaming (GOST 20999 Table 6): feed in, feed out to the initial level; two holes
%
N1 G90 G00 X0 Y0 Z10. (INITIAL LEVEL Z10)
N2 G85 X10. Y20. Z-6. R1. F80. S600 M03 (FIRST HOLE)
N3 X30. (SECOND HOLE)
N4 G80 M05
N5 M30
