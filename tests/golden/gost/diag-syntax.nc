diag-syntax: block syntax (NC1011-NC1014)
%
N1 G01 X0 F100
N2 X1 N3 (NC1012 - the block number is not the first word)
N4 X2 :5 (NC1012 - nor is a main-block number)
: X3 (NC1011 - the main-block character without its number)
N6 /1 X4 (NC1013 - a skip level inside the block)
/2 N7 X5 (NC1013 - a skip level before the block number)
N8 +5 (NC1014 - a sign without an address)
N9 X1.2.3 (NC1014 - a second decimal point)
N10 X6 % (NC1014 - the program-start character inside a block)
25 X7 (NC1014 - digits without an address)
N12 M30
