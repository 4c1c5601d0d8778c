format-lenient: X+53 without DS in lenient mode: fewer digits read as leading zeros omitted, warning NC2008 (S-6.4)
%
N1 G00 X125 (00000125 = 0.125, NC2008)
N2 Y-12 (-0.012, NC2008)
N3 Z00012500 (8 digits, 12.5, no warning)
N4 M02
