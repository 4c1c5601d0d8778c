; NC-110 §2.8.9 (R1/R2, seed lines 3541-3549, 3691-3692), §2.8.9.4, decisions 51-52:
; two R words are R1 and R2, one R is both, no R is the level the tool is at; a block
; with only R or only the depth sets them and drills nothing; R2 changes only with R1.
; Profile cycle-mill: the tool starts at X0 Y0 Z100.
; N2-N3: no R: R1 = R2 = Z100; the hole at X10: XY at Z100, feed to -10, rapid to 100.
; N5-N7: one R: R1 = R2 = 5: XY at Z20, rapid to 5, feed to -10, rapid to 5.
; N9-N11: R5 R15: hole at X30: XY at Z5 (already R1), feed to -10, rapid to R2 15;
;   hole at X40: XY at 15, rapid to 5, feed to -10, rapid to 15.
; N12 R3: R1 = R2 = 3, nothing moves; N13 X50: XY at 15, rapid to 3, feed, rapid to 3.
; N14 Z-20: the depth only, nothing moves; N15 X60: XY at 3, feed to -20, rapid to 3.
; N16 R2 R12: both; N17 X70: XY at 3, rapid to 2, feed to -20, rapid to 12.
N1 S800 F100 M3
N2 G81 Z-10
N3 X10
N4 G80
N5 G Z20
N6 G81 R5 Z-10
N7 X20
N8 G80
N9 G81 R5 R15 Z-10
N10 X30
N11 X40
N12 R3
N13 X50
N14 Z-20
N15 X60
N16 R2 R12
N17 X70
N18 G80
