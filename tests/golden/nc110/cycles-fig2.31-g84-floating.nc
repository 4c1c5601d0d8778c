; NC-110 §2.8.9.3 1), Fig. 2.31 (seed lines 4045-4050; no corpus file): G84 tapping on a
; spindle without an encoder (profile cycle-noencoder), three holes on a circle of 60.
; Annotations ("tapping at point 1, 2, 3") are moved here.
; F315 = S280 x p1.25 x 0.9 (F = S*p*0.9, seed line 4030): guidance, not checked.
; Checks (Table 2.6, decision 54): N92 stores G84 R7 Z-15 (R1 = R2 = 7); each hole:
; rapid in XY (at Z100, then Z7), rapid to R7, feed F315 to Z-15, the spindle reversed
; at the bottom (M13 was clockwise: "spindle ccw"), feed back to R1 Z7 at F315 (RMS is
; 100 %, so no feed_rate event), the spindle forward again; point 3 "X Y60" is X0 Y60
; (a bare address is 0, decision 4); N96 cancels, up to Z50, M5 at the end.
N91 S280F315 T8.8 M6 M13
N92 G84 R7 Z-15
N93 X-51.96 Y-30
N94 X51.96
N95 X Y60
N96 G80 Z50 M5
