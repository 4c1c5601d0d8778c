; comp-corners: the corners of a compensated path, §2.8.7 figures 2.20-2.22 (corpus
; part2/2.8.7-corner-*.nc, 2.8.7-chamfer-fig2.22.nc; their `Z-100` read as Y-100), in one
; path under G41 with T1.1 (radius 5): a square turned clockwise, so every corner turns
; right, outside for the tool on the left, but the last. Checked by hand (decision 74):
; - N10 ends square to N20 on its left: X0 Y5.
; - N20/N21 (figure 2.20): no r, the tool goes to where the offsets meet: X105 Y5.
; - N22 r0 (figure 2.21): it rolls round (100, -100) instead, clockwise on radius 5,
;   from X105 Y-100 to X100 Y-105.
; - N24 b5 (figure 2.22): the chamfer from (5, -100) to (0, -95), moved 5 to its left,
;   meets N23 moved (y = -105) at X2.9289 Y-105 and N25 moved (x = -5) at X-5 Y-97.0711.
; - N25/N26 turns left (inside): the offsets meet at X-5 Y-5; N26 (G40) ends still
;   offset at X-20 Y-5; N27 leaves to X-30 Y20.
N1 T1.1 M6 S1000 M3 F200
N2 G X-20 Y20
N10 G1 G41 X0 Y0
N20 X100
N21 Y-100
N22 r0
N23 X0
N24 b5
N25 Y0
N26 G40 X-20
N27 G X-30 Y20
