tape-spaces: SP and HT are not perceived; inside a number they are reported (GOST 20999 Table 2 note 2, NC1010)
%1
N1	G90	G00	X 1030.	Y -2.5	Z	5. (tabs before words, a space after the address or before the sign - no warning)
N 2 G 01 X1030.5 F 100 (spaces between the address and its number - no warning)
N3 X10 30. (a space between two digits - NC1010, the NC reads X1030.)
N4 Y- 1. Z1 .5 (between the sign and a digit, and between a digit and the point - NC1010 twice)
N5 G0	0 X0 (a tab inside the number of G - NC1010, the NC reads G00)
N6 M30
