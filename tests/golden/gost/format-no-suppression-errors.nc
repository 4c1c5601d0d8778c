format-no-suppression-errors: X+53 without DS: fewer than 8 digits is NC2007 (S-6.5)
%
N1 G00 X125 (3 digits, NC2007)
N2 Y-1 (1 digit, NC2007)
N3 M02
