; gtl-closed-profile: a closed profile as §2.11.8.3 (figure 2.100) writes it: the G21
; block names the last element with s2, the next the first; at the end the last
; element again with s2 and G20 G40 the first. The Z plunge stands between the last
; element's call and the first's (§2.11.8.4). A "D": c1 (r20 about the zero,
; counter-clockwise), l1 (x = 10, up), l5 (y = 15, to -X); travelled counter-clockwise,
; G42 puts T1.1 (radius 5) outside. Checked by hand:
; - l5 meets c1 at x = -/+13.229 (20^2 - 15^2 = 13.229^2); along l5 (to -X) the second
;   is X-13.229 Y15 (s2): the closing corner. Moved 5 outward, y = 20 meets the circle
;   of radius 25 at x = -15 (25^2 - 20^2 = 15^2): N4 goes to X-15 Y20, N5 plunges.
; - c1 runs counter-clockwise to l1 at (10, -17.321) (l1 meets c1 first there, going
;   up); moved, x = 15 meets radius 25 at y = -20: N6 ends at X15 Y-20 after 180
;   deg (from 126.870 to 306.870), then l1 to y = 20 and l5 back to X-15 Y20.
c1 = I0 J0 r20
l1 = X10 Y0, a90
l5 = X0 Y15, a180
N1 T1.1 M6 S1000 M3 F200
N2 G X-40 Y40
N4 G21 G42 l5 s2
N5 Z-10
N6 c1
N7 l1
N8 l5 s2
N9 G20 G40 c1
N10 G Z10
