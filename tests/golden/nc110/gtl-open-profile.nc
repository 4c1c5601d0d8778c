; gtl-open-profile: the open profile of §2.11.8.2, figure 2.98 (corpus part3/
; 2.11.8.2-fig-2.98-open-profile.nc), its definitions as printed: `l1 = XY 25,a` is the
; line through X0 Y25 at 0 deg (an address without a value is 0). From p1 to p2 along
; l1, a fillet r3 into c1, `c1 s2` (the right-hand meeting of c1 and c2), `c2 s2` (the
; second meeting of c2 and l1 along l1), then l1 again. Supplied: the tool, the
; approach N1-N3 and the lift N12. G42 with T1.1's radius 5. Checked by hand:
; - N4 starts beside p1, square to l1 on its right: X-20 Y20 (§2.11.8.2).
; - N6 r3 grows to 8 about the nominal centre (13.267, 28); N7 c1 (r-14, clockwise,
;   the tool on its centre's side) shrinks to 9; N8 c2 (r15) grows to 20.
; - c1 meets c2 at (36.533, 12.618), where the path turns left: an outside corner for
;   the tool on the right. The moved circles meet where (d^2 + 9^2 - 20^2) / 2d = -3.133
;   from c1's centre along the centres' line (d = 15), 8.437 to either side: at
;   X26.867 Y16.563 (the one nearer the corner) and Y33.437. So c1 runs 280.210 deg
;   instead of 232.018 and c2 from there.
; - N11 ends beside p2, square to l1: X90 Y20; G40 ends the compensation after it.
l1 = XY 25,a
p1 = X-20 Y25
p2 = X90 Y25
c1 = I30 J25 r-14
c2 = I45 J25 r15
N1 T1.1 M6 S1000 M3 F200
N2 G X-30 Y30
N3 Z-5
N4 G21 G42 p1
N5 l1
N6 r3
N7 c1 s2
N8 c2 s2
N9 l1
N11 G20 G40 p2
N12 G Z10
