; NC-110 §2.8.9 note 2 ("the dwell is programmed with TMR", seed line 3708), §2.10.1,
; decision 45: the dwell of G82/G89 at the bottom is TMR, in seconds under G94 and in
; spindle revolutions under G95, read when the hole runs; no TMR ever set is 0 s.
; Profile cycle-mill: the tool starts at X0 Y0 Z100.
; N3: G82 before any TMR: hole X10: XY at 100, rapid to 2, feed to -5, dwell 0, rapid 2.
; N4: TMR=2 set inside the cycle: hole X20: the same with dwell 2.
; N7-N9: G95 (F0.1 mm/rev at S600 = 60 mm/min), TMR=3 revolutions = 0.3 s: G89 hole
;   X30: XY at 2, feed to -5, dwell 0.3, feed back to 2.
N1 S600 F100 M3
N2 G82 R2 Z-5
N3 X10
N4 TMR=2
N5 X20
N6 G80
N7 G95 F0.1
N8 TMR=3
N9 G89 R2 Z-5
N10 X30
N11 G80 G94
