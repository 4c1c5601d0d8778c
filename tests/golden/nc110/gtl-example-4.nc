; gtl-example-4: §2.11.10 example 4 (figure 2.109, spec nc110-3 §4.4): elements defined
; once, an open profile (p1 to p2) run eight times under (URT,E25), E25 = 0, 45, ...,
; 315, outlines an 8-spoke star (spokes 20 wide, a hub of radius 10); the START..END
; section runs with the stock allowance UOV=2 (roughing), then UOV=0 and
; (EPP,START,END) runs it again (finishing). Supplied where the manual elides values:
; N2 F300 S1000 M3; profile nc110-mills: T2.2 is a mill of radius 1, so the tool's
; offset is 3 in the roughing and 1 in the finishing.
; Checked by hand:
; - l1 = c2,a180 is y = 10 to -X (c2 on its left); l2 = c2,a45 the line through
;   (7.071, -7.071) at 45 deg; p2 = l3,c1,s2 = (35.355, 35.355), p1 turned 45 deg, so
;   each pass ends where the next one starts: its approach does not move.
; - Pass 1 (roughing, G42 puts the tool outside the star by 3): N16 from X60 Y0 to
;   (50 + 3, 0); N17 c1 grows to 53; N18 r3 to 6; N19 l1 at y = 13; N20 r-3 shrinks to
;   0: the tool turns on its centre (31.385, 13); N21 l2 moved 3 to its right; N24 ends
;   3 beyond p2 along the radius: X37.4767 Y37.4767.
; - The finishing pass is the same path 2 closer to the star: c1 at 51, y = 11, ...
; - After the last pass of each section the transform is 0 again (N27).
N1  (DIS,"GTL WITH ROTATION")
N2  F300 S1000 T2.2 M6 M3
N3  UOV=2
N4  p1=X50 Y0
N5  c1=I0 J0 r50
N6  c2=I0 J0 r10
N7  l1=c2,a180
N8  l3=X0 Y0,a45
N9  l2=c2,a45
N10 p2=l3,c1,s2
N11 X60 Y0
N12 Z-20
"START" N13 E25=0
N14 (RPT,8)
N15 (URT,E25)
N16 G21 G42 p1
N17 c1
N18 r3
N19 l1
N20 r-3
N21 l2
N22 r3
N23 c1
N24 G20 G40 p2
N25 E25=E25+45
N26 (ERP)
N27 (URT,0)
"END" N28
N29 UOV=0
N30 (EPP,START,END)
N31 G0 Z20
N32 X Y M30
