; words-implicit-g: G may be given by an E parameter of class BY (§2.4.5 seed L1548-1551,
; L1907-1909; Table 2.9 GE1 L7779, N804 GE2 RE36 ZE37 L9047; decision 15): the code is
; read when the block runs.
E1=1
E2=0
E3=2
E30=10
; E1 = 1: G01, linear to X10 at F100
GE1 XE30 F100
; a blank between G and E (G E2): E2 = 0, G00: rapid to X10 Y5
G E2 Y5
; E3 = 2: G02, half circle cw from X10 Y5 to X20 Y5, R5: centre X15 Y5
GE3 X20 Y5 R5
; E1 changed to 0 in between: the same block text now moves in rapid, to X0
E1=0
GE1 X0
; with another G word in the block: E2 = 0 with G90, rapid to Y0
GE2 G90 Y0
; the manual's use (L9046-9047 E2=81 ... GE2 RE36 ZE37): E2 = 81 gives the drilling cycle
; G81 (R2, bottom Z-5); the hole at X5: rapid to X5 at Z10, rapid to R Z2, feed to Z-5,
; rapid back to Z2
G0 Z10
E2=81
GE2 R2 Z-5 F100
X5
G80
