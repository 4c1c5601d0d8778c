; gtl-example-2: §2.11.10 example 2 (figure 2.107, corpus part3/2.11.10-gtl-example-2.nc)
; with what the manual leaves out supplied: N12 S1000 F200 M3 T3.3 M6 for "S..M..T3.3M6M..",
; a180 for the A180 of N5 and straight quotes in N1 (the program as printed is
; gtl-example-2-as-printed). A closed pocket, last element l7, first l1, travelled
; clockwise with the fillets r-8 and r-10; l1, l2 and l4 are called more than once.
; G42 with T3.3's radius 5 keeps the tool inside. Checked by hand (the nominal path is
; gtl-example-2-nominal):
; - N15 goes to where l7 (x = -50, up) and l1 (from (-50, 10) to (30, 50)), each moved
;   5 to its right, meet: x = -45 and the line through (-50 + 5 sin 26.565, 10 - 5 cos
;   26.565) = (-47.764, 5.528) at 26.565 deg: X-45 Y6.9098.
; - The fillets shrink by 5: r-8 -> 3, r-10 -> 5, about the nominal centres; c1
;   (r18, counter-clockwise, the tool outside it) grows to 23; c2 (r-14) shrinks to 9;
;   c3 (r10, counter-clockwise) grows to 15.
; - N22: l2 runs through c2's centre (50, 30); its offset, 5 from the centre, meets the
;   circle of radius 9 at X41.173 Y31.756 and X51.756 Y21.173 (the points nearest the
;   nominal corners), 247.498 deg apart clockwise.
; - N35 closes at X-45 Y6.9098, where N15 started.
N1 (DIS,"EXAMPLE 2")
N2 l1=X-50Y10,X30Y50
N3 l2=X30Y50,X70Y10
N4 l3=X70Y0,a-90
N5 l4=X0Y-20,a180
N6 l5=X10Y-20,X0Y0
N7 l6=X0Y0,X-10Y-20
N8 l7=X-50Y0a90
N9 c1=I-10J40r18
N10 c2=I50J30r-14
N11 c3=I40J-20r10
N12 S1000 F200 M3 T3.3 M6
N13 G0X-30Y0
N14 Z-10
N15 G21 G42 l7
N16 l1
N17 r-8
N18 c1
N19 r-8
N20 l1
N21 l2
N22 c2s2
N23 l2
N24 l3
N25 r-10
N26 l4
N27 c3s2
N28 l4
N29 r-8
N30 l5
N31 l6
N32 r-8
N33 l4
N34 r-10
N35 l7
N36 G20G40l1
N37 G0Z0
