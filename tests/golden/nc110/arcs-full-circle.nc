; A full circle written without any axis word (§2.8.1.4 L2320: "if no axis is programmed,
; a full circle of 360 degrees is made"; decision 39: "no axis (or the end on the start)
; is a full circle"). The manual's own G35 example (corpus-2.8.16-G35, N4 "G2 I J") uses
; this form. G29: no G27 profile rule.
; Expected:
;  N1 arc cw XY X10 Y20 Z0 centre X0 Y0 radius 22.3607 sweep 360 (G90: I0 J0 absolute);
;  N2 arc ccw ... centre X0 Y0 ... sweep 360 (G91: I-10 J-20 from the start X10 Y20);
;  N3 arc ccw ... centre X0 Y0 ... sweep 360 (G90, bare I J = I0 J0);
;  clock: three circles of 140.4963 mm at F100 = 252.8933 s, plus the rapid 0.12 s:
;  TIM0 253.0133; no NC4025 warning.
N0 G29 G0 X10 Y20
N1 G2 I0 J0 F100
N2 G91 G3 I-10 J-20
N3 G90 G3 I J
E25 = TIM0
(DIS,E25)
