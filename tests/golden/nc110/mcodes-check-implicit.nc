; M words given by a BY E parameter (ME3, Table 2.9 seed line 7780; decision 15).
; Line 10: five M words: the limit of four (§2.7.8, lines 1889-1890) counts words, so this is NC3014
; at ME3 (10:17) whatever E3 holds: an ME word counts towards the four statically.
; Line 12: E4 = 3 makes ME4 an M03 beside M04: the spindle set conflict (NC3005) that `M04 M03` gets
; statically, checked when the block runs and reported at ME4 (12:5): "M04 and M03 must not be ...".
E3=60
E4=3
G00 X0
; Five M words, the fifth from E3 (M60, in no conflict set).
M03 M08 M10 M41 ME3
; M04 with M03 from E4.
M04 ME4
G00 X10
M30
