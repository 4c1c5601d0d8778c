diag-formats: an error with a note, a warning, an info and, from the profile, a diagnostic without a place
%
N1 G01 X1 X2 F100 (NC3001 - an error, with a note at the first X)
N2 X3 ) (NC1005 - a warning)
N3 M30
trailer (NC1007 - an info)
