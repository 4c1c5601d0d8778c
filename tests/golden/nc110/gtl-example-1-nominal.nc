; gtl-example-1-nominal: gtl-example-1 (§2.11.10 example 1) without G42/G40: the tool
; centre runs on the drawing. Every end point is the digest's derivation
; (spec nc110-3 §4.1), checked on the output to 3 decimals:
;   N12 corner l2/l3 X8 Y8; N13 l3 -> (47.337, 12.441); N14 r3 about (47, 15.422) ->
;   (50, 15.422); N15 l4 -> (50, 24.031); N16 r3 about (47, 24.031) -> (49.464, 25.742);
;   N17 c1 clockwise 55.178 deg -> (46.569, 48.717); N18 r5 about (41.883, 50.460) ->
;   (44.383, 54.790); N19 l1 -> (34.859, 60.288); N20 r5 about (32.359, 55.958) ->
;   (28.617, 59.274); N21 c2 clockwise 53.463 deg -> (11.903, 52.612), the second
;   meeting of c2 and l2 (s2); N22 l2 -> X8 Y8.
N1  (DIS,"EXAMPLE GTL")
N2  l1 = X70 Y40, a150
N3  l2 = X8 Y8, a-95
N4  p1 = l1, l2
N5  l3 = X8 Y8, X70 Y15
N6  l4 = X50 Y, a90
N7  c1 = I70 J40 r-25
N8  c2 = p1, r-20
N9  T1.1 S800 F250 M6 M3 M7
N10 G XY
N11 Z-10
N12 G21 l2
N13 l3
N14 r3
N15 l4
N16 r3
N17 c1
N18 r5
N19 l1
N20 r5
N21 c2 s2
N22 l2
N23 G20 l3
N24 G Z2
N25 G X Y M30
