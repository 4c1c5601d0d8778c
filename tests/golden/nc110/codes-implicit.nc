; Decision 15 (§2.4.5, §2.8 seed lines 1907-1909): GE<n> (BY class) gives the code at run time; it
; must be a decoded code (NC4049) compatible with the block's other G codes (NC3013 at run time).
; What ncc does now: line 15 at 15:5 (the GE1) and line 16 at 16:5 (the G90), the later codes,
; but without the note the static NC3013 puts at the earlier code; line 18 at 18:1 (GE2, the
; earlier code) and line 20 at 20:5 (GE5), both without a note. Expected: the error at the later code
; of the pair (the GE word when it is the later one), with the note at the other, as the static
; check does. Line 22: NC4049 "G05 is not a code of the dialect's table (... Table 2.2)" at the
; GE4 word, as expected. The dry run stops at NC4049.
E1=91
E2=4
E3=9
E4=5
E5=17
; G90 with G91 from E1 (G90 row, column 90 91 = 1).
G90 GE1 X0
GE1 G90 X0
; G04 and G09 from E2 and E3 (one class, j).
GE2 GE3 X0
; G00 with G17 from E5 (the G17 row is all 1).
G00 GE5
; G05 from E4: not decoded.
GE4 X10
M30
