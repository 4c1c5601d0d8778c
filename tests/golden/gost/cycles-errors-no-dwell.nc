Canned cycles with a dwell (G82, G88, G89) need the dwell time P
%
N1 G90 G00 X0 Y0 Z10. S500 M03
N2 G82 X10. Y10. Z-5. R2. F100. (NO P)
N3 G88 X20. (NO P)
N4 G89 X30. (NO P)
N5 G80 M05
N6 M30
