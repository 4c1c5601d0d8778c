; NC-110 §2.8.9.2 (seed lines 3842-3905), decision 53: G83 with K and/or J unloads the
; chips (each peck back to R1, then a rapid to 1 mm above the depth reached; the peck
; times K, default 1, but at least J, default 0); without K and J it breaks the chips
; (pecks of I, a TMR dwell between them, none after the last); the exit goes to R2.
; Profile cycle-mill: the tool starts at X0 Y0 Z100.
; N3-N4 (K1, no J: constant peck 10, "to keep I constant program K=1 without J"):
;   hole X10: XY at 100, rapid to 2, feed to -8, rapid 2, rapid -7, feed -17, rapid 2,
;   rapid -16, feed to -25 (clipped), rapid to 2.
; N6-N7 (J12, no K: K = 1, so the peck 10 is raised to J 12 after the first):
;   hole X20: XY at 2, feed to -8, rapid 2, rapid -7, feed to -19, rapid 2, rapid -18,
;   feed to -25, rapid 2.
; N9-N10 (no K, no J): hole X30: XY at 2, feed -8, dwell 0.5, feed -18, dwell 0.5,
;   feed to -25, rapid to 2.
; N11 (a hole with R1 2 and R2 20): XY at 2, feed -8, dwell, feed -18, dwell, feed -25,
;   rapid to 20.
; N13-N14 (K.5 J3 with R2 30): hole X50: XY at 20, rapid to 2, feed to -6 (I8), rapid 2,
;   rapid -5, feed to -9 (peck 4), rapid 2, rapid -8, feed to -11 (peck 2 raised to
;   J3), rapid 2, rapid -10, feed to -13, ..., until -25: bottoms -6 -9 -11 -13 -15 -17
;   -19 -21 -23 -25, each followed by a rapid to R1 2; the last rapid goes to R2 30.
N1 S800 F100 M3
N2 TMR=0.5
N3 G83 R2 Z-25 I10 K1
N4 X10
N5 G80
N6 G83 R2 Z-25 I10 J12
N7 X20
N8 G80
N9 G83 R2 Z-25 I10
N10 X30
N11 X40 R2 R20
N12 G80
N13 G83 R2 R30 Z-25 I8 K.5 J3
N14 X50
N15 G80
