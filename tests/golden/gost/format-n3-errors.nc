format-n3-errors: block number format N3: fewer or more than three digits is NC2007 (S-6.5)
%
N001 G00 X1
N5 X2 (1 digit, NC2007)
N05 X3 (2 digits, NC2007)
N0005 X4 (4 digits, NC2007)
N010 M02
