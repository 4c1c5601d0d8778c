; gtl-example-3: §2.11.10 example 3 (figure 2.108, corpus part3/2.11.10-gtl-example-3.nc)
; with what the manual leaves out supplied: N2 S1000 F200 T1.1 M6 M3 for "S..F..T1.1M6M..",
; N41 X0 Y0 M30 for "X..Y..M30", and N1's text in quotes (the program as printed is
; gtl-example-3-as-printed). An origin o1 turned 45 deg, tangents to c6, a point p2 where
; two helper circles meet so that both r40 circles touch c1, fillets between elements
; that do not meet. A closed pocket (last element l8, first l1) travelled clockwise; the
; Z plunge N21 stands between the last element's call and the first's (§2.11.8.4).
; G42 with T1.1's radius 5 keeps the tool inside. Checked by hand (the nominal path is
; gtl-example-3-nominal):
; - N20 goes to where l8 (x = 70, down) and l1 (y = -60, to -X) moved 5 to their right
;   meet: X65 Y-55; N21 plunges there.
; - The fillets r-5 (N23, N35, N37) are as large as the tool: the tool turns on their
;   centres, with no move of their own; r12 (N25, counter-clockwise, outside the tool)
;   grows to 17; r40 (N32) grows to 45.
; - c6 (r10, counter-clockwise) grows to 15; c1 (r-15) shrinks to 10; c2 (r40) grows to
;   45; c5 (r13) grows to 18.
; - N38 closes at X65 Y-55.
N1 (DIS,"EXAMPLE 3")
N2 S1000 F200 T1.1 M6 M3
N3 o1=X20Y21a45
N4 l1=X0Y-60a180
N5 l2=X50Y0,a90
N6 c6=o1I-38J-35r10
N7 l3=c6,a135
N8 l4=c6,a-45
N9 l5=X0Y-50,a180
N10 l6=X-50Y-65,a60
N11 l7=X-25Y0,a90
N12 c3=I-65J0r55
N13 c4=I0J80r55
N14 p2=c3,c4
N15 c1=p2,r-15
N16 p3=X40Y80
N17 c2=c1,p3,r40
N18 c5=I55J80r13
N19 l8=X70Y0,a-90
N20 G21 G42 l8
N21 Z-10
N22 l1
N23 r-5
N24 l2
N25 r12
N26 l3
N27 c6
N28 l4
N29 l5
N30 l6
N31 l7
N32 r40
N33 c1
N34 c2
N35 r-5
N36 c5
N37 r-5
N38 l8
N39 G20 G40 l1
N40 G Z
N41 X0 Y0 M30
