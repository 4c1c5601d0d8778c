main-no-digits: the main-block character must be followed by the block number (GOST 20999 §2.6, decision 9, NC1011)
%1
N1 G00 X1.
: G90 G17 G00 X2. F100 S100 M03 T1
:
N4 M30
