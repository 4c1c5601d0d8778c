; gtl-open-profile-nominal: gtl-open-profile (§2.11.8.2, figure 2.98) without G42/G40.
; The end points are the digest's derivation (spec nc110-3 §3.11.1), checked on the
; output: N4 p1 (-20, 25); N5 l1 -> (13.267, 25); N6 r3 about (13.267, 28) -> (16.220,
; 27.471), 79.836 deg; N7 c1 clockwise 232.018 deg -> (36.533, 12.618), the right-hand
; meeting of c1 and c2 (s2); N8 c2 counter-clockwise 124.364 deg -> (60, 25), the
; second meeting of c2 and l1 (s2); N9 l1 -> p2 (90, 25).
l1 = XY 25,a
p1 = X-20 Y25
p2 = X90 Y25
c1 = I30 J25 r-14
c2 = I45 J25 r15
N1 T1.1 M6 S1000 M3 F200
N2 G X-30 Y30
N3 Z-5
N4 G21 p1
N5 l1
N6 r3
N7 c1 s2
N8 c2 s2
N9 l1
N11 G20 p2
N12 G Z10
