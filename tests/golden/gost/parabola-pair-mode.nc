parabola-pair-mode: a three-point parabola broken by a change of motion mode is NC4009 (GOST 20999 §4.4.2, the two blocks follow each other)
%
N1 G90 G17 G00 X0 Y0 Z0 (P0 0 0 0)
N2 G06 X5. Y5. F100. (block 1, the intermediate point, no motion yet)
N3 G01 X10. Y0 (NC4009, G01 instead of the end point)
N4 M02
