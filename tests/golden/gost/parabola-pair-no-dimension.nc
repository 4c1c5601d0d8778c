parabola-pair-no-dimension: the block after the intermediate point must hold the end point, NC4009 (GOST 20999 §4.4.2)
%
N1 G90 G17 G00 X0 Y0 Z0 (P0 0 0 0)
N2 G06 X5. Y5. F100. (block 1, the intermediate point)
N3 M08 (NC4009, a block without dimension words)
N4 G00 X0 Y0 (a rapid, no parabola is pending)
N5 M02
