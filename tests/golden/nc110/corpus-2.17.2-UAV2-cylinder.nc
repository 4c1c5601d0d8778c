; NC-110 §2.17.2 (seed lines 10976-11025, figures 2.146-2.147), decision 83: a GTL
; profile on a cylinder of radius 60, B the rotary axis, V the virtual axis along its
; developed circumference (mode 2), in the plane V Y. Profile uav. As printed but for
; N1, whose quotes around DIS are a misprint (the seed writes ("DIS", "EXAMPLE")); the
; seed's two N19 blocks and its missing N4 stay.
; E31 = 2 * 3.1415 * 60 = 376.98: l1 runs along Y20 from V0 to the whole circumference.
; c1 (V80 Y45, r25) touches l1 from above; c2 and c3 (r-25) are clockwise; l2 and l3
; are their tangents; c4 (r15) touches c3 and l1.
; (UAV,0) at V376.98: B = 376.98 / 60 rad = 359.9894 degrees (the manual's 3.1415 is
; short of pi), and V goes back to 0.
N1  (DIS, "EXAMPLE")
N2  T1.1 M6
N3  GXY20 Z10
N5  G0 G94 B0 S2000 M3
N6  E30=60
N7  (UAV, 2, B, V, E30)
N8  (DPI, V, Y)
N9  p1=V0 Y20
N10 E31=2*3.1415*E30
N11 p2=VE31 Y20
N12 l1=p1, p2
N13 c1=I80 J45 r25
N14 c2=I140.71 J35 r-25
N15 c3=I180 J35 r-25
N16 l2=c1, c2
N17 l3=c2, c3
N18 c4=c3, l1, r15
N19 G21 G41 p1 F500
N19 Z-12
N20 l1
N21 c1
N22 l2
N23 c2
N24 l3
N25 c3
N26 c4
N27 l1
N28 G20 G40 p2
N29 (UAV, 0)
N30 G Z20
N99 M30
