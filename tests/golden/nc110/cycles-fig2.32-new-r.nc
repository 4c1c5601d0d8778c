; NC-110 §2.8.9.4 1), Fig. 2.32 (seed lines 4170-4180; no corpus file): a block X Y R
; inside an active cycle changes R, and one R sets both R1 and R2 (decision 52): "the
; holes at points 3 and 4 are drilled with R-13, Z-42" (seed lines 4206-4211).
; The point numbers printed before N38-N41 are left out.
; Checks: holes 1 (15,15) and 2 (65,15) with R3 Z-42: XY (at Z100, then Z3), rapid to
; Z3, feed to Z-42, rapid to Z3; N40 Y85 R-13: XY at Z3, rapid to Z-13, feed to Z-42,
; rapid back to Z-13 (R2 = R1 = -13); N41 X15: XY at Z-13, feed to Z-42, rapid to
; Z-13; N42 cancels and goes up to Z50.
N35 (DIS,"...............")
N36 S1000 F100 T4.4 M6
N37 G81 R3 Z-42 M3
N38 X15 Y15
N39 X65
N40 Y85 R-13
N41 X15
N42 G80 Z50 M5
