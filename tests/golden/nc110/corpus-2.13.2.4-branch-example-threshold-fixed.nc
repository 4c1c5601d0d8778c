; corpus-2.13.2.4-branch-example-threshold-fixed: the threshold example of
; §2.13.2.4 (seed L8599-8620) with its two misprints corrected: the BLT jumps to
; LAB1 (as its annotation says, not LAB), and (BBS,LAB2) is (BNC,LAB2).
; Expected (derived, corpus digest §2.13.2.4 threshold): the loop runs 4 times,
; E41 = 0.0165, 0.018, 0.0195, 0.021; then |E42-E41| < 0.0001 and
; (DIS, E41) shows "E41=0.021" (an LR parameter, 10 significant digits:
; the sum is 0.021000000000000005 as a double).
; Added: the counter E30 of the passes, shown at the end ("E30=4"), and M30.
E42=0.021
E41=0.015
E47=0.0015
E43=0.0001
"LAB2" E41=E41+E47
E30=E30+1
E44= ABS (E42-E41)
(BLT, E44, E43, LAB1)
(BNC, LAB2)
"LAB1" (DIS, E41)
(DIS, E30)
M30
