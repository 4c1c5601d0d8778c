comp-group-d: G40-G44 form group d (GOST 20999 Table 4 note 3, ncc decision 15) - one compensation at a time; G43/G44 add/subtract the length of the offset on Z, G41/G42 use its radius (decision 28)
%
N1 G00 Z50.
N2 H1 (offset number 1 - no compensation is active, so no event)
N3 G43 Z10. (+75 on Z; positions stay those of the programmed point)
N4 G44 (-75)
N5 G41 X10. (cutter compensation left, radius 5; cancels the tool position offset)
N6 G42 (right)
N7 G43 (cancels the cutter compensation)
N8 G40 (cancels both)
N9 M30
