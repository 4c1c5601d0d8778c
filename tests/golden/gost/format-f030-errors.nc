format-f030-errors: F030 without DS: at most 3 digits, no decimal point
%
N1 G01 X1 F1000 (4 digits, NC2012)
N2 X2 F1.5 (no DS, NC2004)
N3 M02
