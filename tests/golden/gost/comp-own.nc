comp-own: with g43_g44 = { group = "own" } G43/G44 do not cancel cutter compensation and may share a block with G41/G42 (GOST 20999 Table 4 notes 3-4); G40 cancels both
%
N1 G00 D1
N2 G41 (cutter compensation only)
N3 G43 Z10. (the tool position offset joins it)
N4 G42 G44 (both changed in one block)
N5 G40 (cancels both)
N6 M30
