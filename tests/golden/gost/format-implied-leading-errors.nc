format-implied-leading-errors: S-6.5 rows of X+053 and F031 that an implied-point format rejects
%
N1 X123456789 (9 digits > a + b = 8, NC2012)
N2 X12.5 (no DS, a decimal point is NC2004)
N3 X.03 (NC2004)
N4 X1030. (NC2004)
N5 X123456. (NC2004)
N6 X1.2345 (NC2004)
N7 X1.2500 (NC2004)
N8 X (no digits, NC2002)
N9 X- (NC2002)
N10 X. (NC2002)
N11 F150.5 (F031 without DS, NC2004)
N12 S12345 (S04, at most 4 digits, NC2012)
N1000 M05 (N03, at most 3 digits, NC2012)
N14 M02
