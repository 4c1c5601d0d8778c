; gtl-example-1: §2.11.10 example 1 (figure 2.106, corpus part3/2.11.10-gtl-example-1.nc,
; the two columns in block order). A closed profile, last element l2, first l3, with
; fillets r3 r3 r5 r5 and `c2 s2` (the second c2/l2 meeting), under G42 with T1.1's
; radius 5: the tool outside the part, which the profile goes round counter-clockwise.
; Checked by hand (the nominal path is gtl-example-1-nominal):
; - N12 goes to where l2 and l3 moved 5 to their right meet: l3 runs at 6.442 deg, so
;   its offset is the line through (8 + 5 sin 6.442, 8 - 5 cos 6.442) = (8.561, 3.032);
;   l2 at -95 deg moves to the line through (8 - 5 cos 5, 8 + 5 sin 5) = (3.019, 8.436):
;   they meet at X2.4862 Y2.3457.
; - Fillets grow by the radius: r3 -> 8 about the same centres (47, 15.422), (47,
;   24.031); r5 -> 10 about (41.883, 50.460), (32.359, 55.958). c1 (r-25, clockwise)
;   shrinks to 20, c2 (r-20) to 15: the tool is on their centres' side.
; - Each element ends at the offset of its nominal end, the normal to it 5 long:
;   N13 ends at (47.337, 12.441) + 5 (sin 6.442, -cos 6.442) = X47.8975 Y7.4728; N15 at
;   (50, 24.031) + (5, 0) = X55 Y24.0313.
; - N22 returns to X2.4862 Y2.3457 and G40 ends the compensation after it; N24 lifts
;   there.
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
N12 G21 G42 l2
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
N23 G20 G40 l3
N24 G Z2
N25 G X Y M30
