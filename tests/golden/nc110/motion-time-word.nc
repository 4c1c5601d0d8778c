; The time word t (§2.7.5, seed L1727-1733): under G94 "the time in seconds needed to
; pass the segment defined in the block (the block's F is the ratio of the segment's
; length to the programmed t)", valid in its block only (decision 50: "feed moves at
; ... the block's t").
; Expected: N1 needs no F (t gives the block's own feed): a line in 5 s; N2 an arc in
; 3 s (t applies to the segment of any feed block, not only G01); TIM0 8 s. N3 has
; neither F nor t: NC4001.
N1 G1 X10 t5
N2 G2 X20 Y0 I15 J0 t3
E25 = TIM0
(DIS,E25)
N3 G1 X30
