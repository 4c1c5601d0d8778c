comp-same-block: a D or H word in the block of G41/G42/G43/G44 is the offset that block's compensation takes effect with (GOST 20999 §3.3.5, ncc decision 28)
%
N1 G00 Z50.
N2 G43 H1 Z10. (+75)
N3 G44 H2 (-110)
N4 G41 D1 X10. (left, radius 5)
N5 G42 D2 (right, radius 4.25)
N6 G40
N7 M30
