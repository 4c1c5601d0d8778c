; Helix errors where K and the travel disagree (§2.8.1.6 L2520, L2555-2560; decision 41),
; ncc check. G29: no G27 profile rule.
; Expected: NC4007 at the K word of N2 (12:24) and N4 (14:29), counting turns of the
; pitch K (not radians); NC4066 at the K word of N6 (16:27): "the helix pitch K0 must be
; greater than zero".
;  N2 a 90 deg arc with Z-3 at K2: the travel needs 1.5 turns, the arc allows 0.25 plus
;     whole turns.
;  N4 Z-5.512 at K2 with the 270 deg arc: 0.012 mm from 2.75 turns, beyond 0.01.
;  N6 K0: no pitch.
N0 G29 G0 X10 Y0 Z0
N1 G1 X10 F100
N2 G3 X0 Y10 Z-3 I0 J0 K2
N3 G0 X10 Y0 Z0
N4 G3 X0 Y-10 Z-5.512 I0 J0 K2
N5 G0 X10 Y0 Z0
N6 G3 X0 Y-10 Z-5.5 I0 J0 K0
