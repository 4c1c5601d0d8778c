; gtl-corners: the connections of §2.11.9 under compensation (§2.8.7). A square
; 40 x 30 travelled counter-clockwise from the zero, G42: T1.1 (radius 5) outside.
; Checked by hand:
; - N4 (l1) ends at a plain corner: l1 (y = 0) and l2 (x = 40) moved 5 outward meet
;   at X45 Y-5.
; - N8 b5 (§2.11.9.3: set back 5 along each line) joins l2 and l3 by the line from
;   (40, 25) to (35, 30), at 135 deg. Moved 5 outward it runs through (43.536, 28.536):
;   it meets l2 moved (x = 45) at X45 Y27.0711, where N6 ends, and l3 moved (y = 35) at
;   X37.0711 Y35, where the chamfer ends.
; - N10 r0: the tool rolls round the corner (0, 30) on a radius of 5, from X0 Y35 to
;   X-5 Y30, counter-clockwise 90 deg (figure 2.21), where the offsets would meet at
;   X-5 Y35.
; - N12 closes at X-5 Y-5, the corner of l4 and l1 moved.
l1 = X0 Y0, a0
l2 = X40 Y0, a90
l3 = X0 Y30, a180
l4 = X0 Y0, a-90
N1 T1.1 M6 S1000 M3 F200
N2 G X-20 Y-20
N3 G21 G42 l4
N4 l1
N6 l2
N8 b5
N9 l3
N10 r0
N11 l4
N12 G20 G40 l1
N13 G X-20 Y-20
