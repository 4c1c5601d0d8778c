comp-block: with g43_g44 = { persistence = "block" } G43/G44 act in their block only (GOST 20999 Table 4 note 4); in group d the cutter compensation they suspend comes back after the block
%
N1 G00 H1
N2 G43 Z10. (+75 in this block only)
N3 Z20. (no offset any more)
N4 G41 (cutter compensation)
N5 G44 Z5. (-75 in this block, the compensation suspended)
N6 X5. (cutter compensation left again)
N7 G40
N8 M30
