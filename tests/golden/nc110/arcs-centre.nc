; Arcs by their centre (§2.8.1.4, L2320-2386; decision 39): I and J are the centre's
; abscissa and ordinate, absolute under G90, from the start under G91. An end point equal
; to the start is a full circle. G29: no G27 profile rule. The clock after N4 pins the
; lengths at F600 (10 mm/s).
; N1 G90: from X10 Y0 counter-clockwise about X0 Y0 to X0 Y10: radius 10, 90 deg.
; N2 G90 clockwise about X0 Y0 back to X10 Y0: 90 deg.
; N3 G90 end = start: a full circle, 360 deg (62.83185 mm).
; N4 G91: X-20 Y0 from X10 Y0 is X-10 Y0; I-10 J0 from the start is the centre X0 Y0:
;   a half circle counter-clockwise, 180 deg.
; Clock: rapid 10/10000 min = 0.06 s; arcs 15.70796 + 15.70796 + 62.83185 + 31.41593 =
;   125.6637 mm at 10 mm/s = 12.56637 s: TIM0 12.62637.
; N5 G91 G2 X0 Y0 I10 J0: a full circle clockwise about X0 Y0 (from X-10 Y0).
N0 G29 G0 X10 Y0
N1 G3 X0 Y10 I0 J0 F600
N2 G2 X10 Y0 I0 J0
N3 G3 X10 Y0 I0 J0
N4 G91 G3 X-20 Y0 I-10 J0
E25 = TIM0
(DIS,E25)
N5 G2 X0 Y0 I10 J0
