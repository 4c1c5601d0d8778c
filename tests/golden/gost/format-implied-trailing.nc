format-implied-trailing: S-6.5 rows of X+530 without DS (trailing zeros omitted, digits align left from the first integer digit)
%
N1 G00 X00012 (00012000 = 12.000)
N2 X000125 (00012500 = 12.500)
N3 X1 (10000000 = 10000.000)
N4 X-0001 (00010000 = -10.000)
N5 X00000001 (00000001 = 0.001)
N6 M02
