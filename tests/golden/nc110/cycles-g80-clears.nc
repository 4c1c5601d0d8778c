; NC-110 §2.8.9 (G80 "cancels the canned cycles", Table 2.6), decision 52: G80 clears
; the stored operands, so a K written for an earlier cycle does not carry over.
; The tool starts at 0 0 0.
; G83 I5 K.5 is cancelled; the new G83 R2 Z-10 I5 has no K and no J: chip breaking:
;   hole X10: XY at Z0, rapid to 2, feed to -3, dwell 1 (TMR), feed to -8, dwell 1,
;   feed to -10, rapid to 2.
; G84 K1 is cancelled; the new G84 has no K: it taps at F (linear moves, not thread):
;   hole X20: XY at 2, feed to -10, spindle ccw, feed to 2, spindle cw.
S500 F100 M3
TMR=1
G83 R2 Z-10 I5 K.5
G80
G83 R2 Z-10 I5
X10
G80
G84 R2 Z-10 K1
G80
G84 R2 Z-10
X20
G80
