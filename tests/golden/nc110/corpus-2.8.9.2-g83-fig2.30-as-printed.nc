; Copy of corpus part2/2.8.9.2-G83-fig2.30-example.nc as printed in N61 (NC-110 §2.8.9.2,
; Fig. 2.30, seed line 3969): (DIS,”TWIST DRILL D=6) opens its text with a typographic
; quote and never closes it, which ncc must reject at 6:10, naming the character ”
; (U+201D) and that texts are enclosed in plain " quotes. F50 added to N63 and the elided
; N66 "G.. X.. Z.." left out, as in the corrected copy corpus-2.8.9.2-g83-fig2.30.
N61 (DIS,”TWIST DRILL D=6)
N62 G97 S1000 T3.3 M6 M3 M7
N63 G83R5 Z-120 I20 K.8 J6 F50
N64 X0 Y0
N65 G80
