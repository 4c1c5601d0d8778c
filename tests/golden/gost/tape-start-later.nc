tape-start-later: a tape start marker may stand only before the first program (GOST 20999 §1.8, decision 1, NC1021)
%%1 (tape start marker and program 1 - correct)
N1 G00 X1.
N2 M02
% %2 (a marker before program 2 - NC1021)
N1 G00 X2.
N2 M02
%%3 (and before program 3 - NC1021)
N1 G00 X3.
N2 M30
