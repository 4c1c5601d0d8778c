; gtl-example-3-nominal: gtl-example-3 (§2.11.10 example 3) without G42/G40. The end
; points are the digest's derivation (spec nc110-3 §4.3), checked on the output:
;   c6 about (17.879, -30.619); N20 corner l8/l1 (70, -60); N22 l1 -> (55, -60); N23 r-5
;   -> (50, -55); N24 l2 -> (50, -53.569); N25 r12 -> (46.485, -45.083); N26 l3 ->
;   (24.950, -23.548); N27 c6 a half circle -> (10.808, -37.690); N28 l4 -> (23.118, -50);
;   N29 l5 -> (-41.340, -50); N30 l6 -> (-25, -21.699); N31 l7 -> (-25, 0); N32 r40 about
;   (-65, 0), the helper c3's centre -> (-52.203, 37.898); N33 c1 about p2 (-47.404,
;   52.109) -> (-34.475, 59.716); N34 c2 about (0, 80), the helper c4's centre ->
;   (38.190, 68.103); N35 r-5 -> (46.307, 70.334); N36 c5 -> (62.222, 69.191); N37 r-5
;   -> (70, 65.033); N38 l8 -> (70, -60).
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
N20 G21 l8
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
N39 G20 l1
N40 G Z
N41 X0 Y0 M30
