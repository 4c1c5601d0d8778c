; Motions that need the canned cycle cancelled first (§2.8.9 note 4, Table 2.4; decision
; 52): G02, G03, G06, G33 and G79 while G81 is active are NC4051, reported at the code.
; ncc check. G29: no G27 profile rule.
; Expected: NC4051 "G02 cannot be used while canned cycle G81 is active: cancel the cycle
; with G80 first" at 9:4, and likewise G03 10:4, G06 11:4, G33 12:4, G79 13:4. After
; G80 (N7) G02 is accepted (N9).
N0 G29 G1 X10 F100 S100 M3
N1 G81 R2 Z-10
N2 G2 X0 Y10 I0 J0
N3 G3 X10 Y0 I0 J0
N4 G06 X1
N5 G33 Z-5 K1
N6 G79 X0
N7 G80
N8 G0 X10 Y0 Z0
N9 G2 X0 Y10 I0 J0
