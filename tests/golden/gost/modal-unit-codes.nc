modal-unit-codes: the unit codes are the profile's (unit_codes, GOST 20999 §3.2.2, Table 4 note 1); here G20 inch / G21 mm, undefined on the default profile
%
N1 G20 G00 X1. (inches)
N2 G21 X10. (millimetres - X1 in is 25.4 mm, the move goes to X10 mm)
N3 M30
