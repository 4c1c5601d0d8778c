; comp-fig-2.23: the full program of §2.8.7, figure 2.23 (corpus part2/
; 2.8.7-G41-G40-fig2.23-example.nc): a closed outer contour travelled clockwise, G41
; keeps T1.1 (radius 5) outside; `r0` (N6) rolls the tool round the corner before the
; arc N7, `r-2` (N8) is a clockwise fillet between N7 and N9; G40 stands in N15, the
; last block of the profile, and N16 leaves it (decision 74). Checked by hand:
; - N4 ends square to N5 (from (85, 50) to (100, 23), direction (0.4856, -0.8742)) on
;   its left: X89.3708 Y52.4282; N5 ends at (100, 23) moved the same: X104.3708 Y25.4282.
; - N6: at (100, 23) the path turns right, an outside corner for the tool on the left:
;   it rolls clockwise round the corner on radius 5 to the start of N7 moved along N7's
;   radius from (110, 0): (100, 23) + 5 (0.3987, -0.9171) = X101.9936 Y18.4146.
; - N7 (r 25.080 counter-clockwise, the tool on its centre's side) shrinks to 20.080;
;   N8 r-2, clockwise, the tool outside it, grows to 7; N11 (r 8.657 counter-clockwise)
;   shrinks to 3.657; N12 and N14 (r 20, clockwise) grow to 25.
; - N15 (G40) ends square to itself at (85, 50) on its left, still offset:
;   X83.3916 Y54.7342; N16 leaves to X85 Y60 as programmed.
N1 S1500 T1.1M6
N2 G X85 Y60 M3
N3 Z-12
N4 G1 G41 X85 Y50 F220
N5 X100 Y23
N6 r0
N7 G3 Y-23 I110 J F180
N8 r-2
N9 G1 X85 Y-50
N10 X31.441 Y-31.803
N11 G3 X20 Y-40 I28.657 J-40 F100
N12 G2 X-20 I J-40 F250
N13 G1 Y F220
N14 G2 X-6.433 Y18.937 I J F250
N15 G1 G40 X85 Y50 F220
N16 G X85 Y60
N17 Z2
