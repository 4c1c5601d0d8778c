; Feed errors (§2.8.1.2 L2078, §2.7.5, §2.8.13; decisions 38, 50). ncc check runs the
; program dry and reports each at its block. G29 keeps the G27 profile rule out of the way.
; Expected:
;  N1 G01 before any F: NC4001 "linear interpolation needs a feed rate, but no F has been
;     programmed in this feed mode" (12:1).
;  N2 G02 lacks the same F: not said again (NC4001 is said once until an F or another
;     feed mode comes).
;  N5 after G95 the F of G94 no longer counts: NC4001 (16:1).
;  N6 the time word t under G95: NC4073 "the time word t is for feed per minute (G94)
;     only" (17:16, at t).
;  N8 G93 block without its own F: NC4014 (19:1).
N0 G29
N1 G1 X10
N2 G2 X0 Y10 I0 J0
N3 G1 X20 F100
N4 G95 S100 M3
N5 G1 X30
N6 G1 X40 F0.1 t5
N7 G93 G1 X50 F2
N8 X60
