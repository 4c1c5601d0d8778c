parabola-pair-end: the program ends before the end point of a three-point parabola, NC4009 (GOST 20999 §4.4.2, §1.9)
%1
N1 G90 G17 G00 X0 Y0 Z0 (P0 0 0 0)
N2 G06 X5. Y5. F100. (block 1, the intermediate point)
N3 M02 (NC4009, the end block has no dimension word)
%2
N1 G90 G17 G00 X0 Y0 Z0 (P0 0 0 0)
N2 G06 X5. Y5. F100. M02 (NC4009, the program ends in the block of the intermediate point)
