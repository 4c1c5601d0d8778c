; G19 is the YZ plane (§2.8.1.5, Table 2.2; decision 39): I is the Y of the centre, J the
; Z; G03 turns from +Y towards +Z (seen from +X). G29: no G27 profile rule.
; N2 from Y0 Z0 counter-clockwise about Y0 Z10 to Y10 Z10: radius 10, 90 deg.
; N3 clockwise back to Y0 Z0: 90 deg.
; N4 a helix along X (the plane's normal): the end on the start in the plane is a full
;   circle; X-6 with the pitch K2 is 3 turns: sweep 1080 deg (decision 41).
N0 G29
N1 G19
N2 G3 Y10 Z10 I0 J10 F100
N3 G2 Y0 Z0 I0 J10
N4 G3 Y0 Z0 X-6 I0 J10 K2
