format-no-suppression: X+53 without DS: exactly a + b = 8 digits, no zeros omitted (S-6.5)
%
N1 G00 X00012500 (12.5)
N2 Y-00000001 (-0.001)
N3 Z12345678 (12345.678)
N4 M02
