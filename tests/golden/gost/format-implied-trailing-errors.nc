format-implied-trailing-errors: X+530 without DS rejects more than a + b digits and a decimal point
%
N1 G00 X000000001 (9 digits > 8, NC2012)
N2 X12.5 (no DS, NC2004)
N3 M02
