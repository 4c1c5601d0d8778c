G82 drilling with dwell (GOST 20999 Table 6): feed in, dwell P seconds at the bottom, rapid out; two holes
%
N1 G90 G00 X0 Y0 Z10. (INITIAL LEVEL Z10)
N2 G82 X10. Y20. Z-8. P1.5 R2. F120. S1000 M03 (FIRST HOLE, DWELL 1.5 S AT Z-8)
N3 X30. (SECOND HOLE, SAME DEPTH, R AND DWELL)
N4 G80 M05
N5 M30
