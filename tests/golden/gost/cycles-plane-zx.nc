Canned cycles in the ZX plane (G18): the drilling axis is Y, the hole position is given by Z and X
%
N1 G90 G18 G00 X0 Y10. Z0 S1000 M03 (INITIAL LEVEL Y10)
N2 G81 X10. Y-5. Z-20. R2. F100. (HOLE AT X10 Z-20, R AT Y2, BOTTOM AT Y-5)
N3 X30. Z-25. (SECOND HOLE)
N4 G83 X40. Y-7. Q4. (G83 ALONG Y AT X40 Z-25, R2 KEPT, PECKS 4, 4, 1)
N5 G80 M05
N6 M30
