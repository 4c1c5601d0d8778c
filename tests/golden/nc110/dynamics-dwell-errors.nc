; Dwell limits (§2.10.1 L4955; decision 45), ncc check. G29: no G27 profile rule.
; Expected (NC4065 at the G04 block, column 1):
;  N2 TMR=61 under G94: "dwell time TMR=61 exceeds 60 s" (11:1).
;  N5 TMR=30001 under G95: "dwell time TMR=30001 exceeds 30000 revolutions (G95)" (14:1).
;  N8 G95 with the spindle stopped (M05 in N7): "dwell time TMR=5 counts spindle
;     revolutions (G95), and the spindle is not turning" (17:1); also after a move (N9,
;     18:1), whose G95 feed move is itself NC4075 (no spindle speed, no feed).
;  N10 TMR=-1: NC4048 "TMR cannot be set to -1: it must not be negative" (19:9, at the value).
N0 G29
N1 TMR=61
N2 G4
N3 G95 S600 M3
N4 TMR=30001
N5 G4
N6 TMR=5
N7 M5
N8 G4
N9 G1 G4 X10 F0.1
N10 TMR=-1
