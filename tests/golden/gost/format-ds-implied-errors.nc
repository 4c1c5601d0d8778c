format-ds-implied-errors: DS with ds_integer_rule = implied: the limits of both readings
%
N1 X123456789 (no point, 9 digits > 8, NC2012)
N2 X123456. (6 integer digits, NC2005)
N3 X1.2345 (4 fraction digits, NC2006)
N4 M02
