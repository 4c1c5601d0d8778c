; Copy of corpus part2/2.8.9.1-G82-TMR-example.nc (NC-110 §2.8.9.1, seed lines 3734-3739):
; "in this example the dwell is 2 seconds".
; Changed: the excerpt programs no F and a cycle feeds, so F100 is added to N34.
; Checks: G82 stores the cycle (no motion in N34); T6 selects tool 6 with corrector 0
; (decision 11), not loaded; the one hole at (35,150): XY at the start height Z100,
; rapid to R3, feed to Z-100, dwell TMR = 2 s (G94: seconds, decision 45), rapid to R3;
; G80 cancels and moves nothing.
N33 TMR=2
N34 G82 R3 Z-100 T6 M13 F100
N35 X35 Y150
N36 G80
