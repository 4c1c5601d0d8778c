; NC-110 Table 2.6 (seed lines 3584-3690): the way out of G85, G86 and G89.
; G85 and G89: "working feed to R1, rapid to R2 if programmed" (at F: RMS is only the
; tapping return, decision 54); G86: the spindle stops at the bottom, "rapid" out, and
; "the spindle starts" with the feed of the next hole, in its last direction; G89 dwells
; TMR at the bottom.
; Profile cycle-mill: the tool starts at X0 Y0 Z100.
; N3 (RMS=50 has no effect here), N4 G85 R2 R10: hole X10: XY at 100, rapid to 2, feed
;   F100 to -20, feed back to R1 2 (no feed_rate event), rapid to R2 10.
; N6 G86 R2 (after M4): hole X20: XY at 10, rapid to 2, feed to -20, spindle stop,
;   rapid to 2. Hole X30: XY at 2, spindle ccw (restart), feed to -20, spindle stop,
;   rapid to 2.
; N10 M3, TMR=1.5, N12 G89 R2 R10: hole X40: XY at 2, feed to -20, dwell 1.5, feed to
;   2, rapid to 10. Hole X50 with R5 (R1 = R2 = 5): XY at 10, rapid to 5, feed to -20,
;   dwell 1.5, feed back to 5, no further move.
N1 S600 F100 M3
N2 G Z100
N3 RMS=50
N4 G85 R2 R10 Z-20
N5 X10
N6 G80
N7 M4
N8 G86 R2 Z-20
N9 X20
N10 X30
N11 G80 M3
N12 TMR=1.5
N13 G89 R2 R10 Z-20
N14 X40
N15 X50 R5
N16 G80
