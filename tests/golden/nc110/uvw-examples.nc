; uvw-examples: the axis-parallel corrections of §2.9, figures 2.37-2.42 (corpus part3/
; 2.9-uvw-example-*.nc; spec nc110-3 §1.4), one after the other with T1.01 (corrector 1,
; radius R = 5) and what the manual elides supplied (S1000 F200, the moves between the
; figures). u, v, w move the programmed point along the plane's abscissa, ordinate and
; normal by R times the factor, in their block only (decision 76). The digest's
; derivation, checked on the output:
; - 2.37: N7 X0 Y15 (10 + R); N8 X35 Y15 (40 - R); N9 X35 Y30.
; - 2.38 (modal G0, as printed): N14 X0 Y5; N15 X45 Y5; N16 X45 Y30.
; - 2.39 (inside the 40 x 40 square): (-15, -15), (15, ·), (·, 15), (-15, ·), (·, -15).
; - 2.40 (outside it): (-25, -25), (25, ·), (·, 25), (-25, ·), (·, -25).
; - 2.41: Y15, then X30, Y-15, X-30.
; - 2.42 (a rotary axis B turning in the block): N53 X35; N54 X30 while B turns to 360.
N5  T1.01 M6 S1000 F200 M3
N6  G X Y30
N7  G1 Y10 v1
N8  X40 u-1
N9  Y30
N13 G X Y
N14 Y10 v-1
N15 X40 u1
N16 Y30
N23 G X Y
N24 G1 Z-10
N25 X-20 Y-20 u1 v1
N26 X20 u-1
N27 Y20 v-1
N28 X-20 u1
N29 Y-20 v1
N30 G X Y
N33 G X-35 Y-35
N34 Z-10
N35 G1 X-20 Y-20 u-1 v-1
N36 X20 u1
N37 Y20 v1
N38 X-20 u-1
N39 Y-20 v-1
N40 GZ
N43 G X-30 Y
N44 G1 Y20 v-1
N45 X30
N46 Y-20 v1
N47 X-30
N52 G X40 Y B0
N53 G1 X30 u1
N54 X25 B360 u1
N55 G X40
