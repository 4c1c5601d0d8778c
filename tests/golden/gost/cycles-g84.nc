G84 tapping (GOST 20999 Table 6): feed in turning in the set direction, reverse at the bottom, feed out, forward again
%
N1 G90 G00 X0 Y0 Z10. (INITIAL LEVEL Z10)
N2 G84 X10. Y20. Z-12. R3. F150. S100 M03 (RIGHT-HAND TAP, CW IN, CCW OUT, CW AGAIN)
N3 X30. (SECOND HOLE)
N4 X50. M04 (LEFT-HAND TAP, CCW IN, CW OUT, CCW AGAIN)
N5 G80 M05
N6 M30
