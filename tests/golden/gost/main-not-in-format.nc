main-not-in-format: an NC whose format descriptor has no colon has no main blocks (GOST 20999 §9.2, NC1017)
%1
N1 G00 X1.
:2 G90 G17 G00 X2. F100 S100 M03 T1
N3 M30
