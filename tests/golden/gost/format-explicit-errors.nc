format-explicit-errors: S-6.5 rows of X+053 rejected with DS (default profile)
%
N1 X01234567 (integer 1234567, 7 > 5 integer digits, NC2005)
N2 X1234567 (NC2005)
N3 X123456789 (9 integer digits, NC2005)
N4 X123456. (6 integer digits, NC2005)
N5 X1.2345 (4 fraction digits > 3, NC2006)
N6 X (no digits, NC2002)
N7 X- (NC2002)
N8 X. (NC2002)
N9 M02
