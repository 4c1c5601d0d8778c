; NC-110 §2.17.1.1 (seed lines 10846-10890, figures 2.143-2.144), decision 83: the
; polar mode's profile in GTL, on the virtual axes U V. Profile uav. The seed's OCR
; damage read as meant (the -as-printed case keeps it): N5 "C-" is C0, N11 "VO" is
; V0, N12 "UOV-20" is U0 V-20, N13 "125" is I25.
; (UAV,1,XC,UV,10) at X80 C0: U80 V0; nothing may come within 10 of the centre.
; p1 = U20 V0; l1 through it at 90 degrees (U = 20, upwards); c1 about U0 V35, r-25
; (clockwise); l2 through U-15 V0 at -90 (U = -15, downwards); l3 through U0 V-20 at 0
; (V = -20); c2 about U25 V-30, r-25. The closed profile from p1 joins them with the
; fillets r3, r4, r5, r5, r3; the tool (corrector 1, radius 5) goes on the right.
N1  T1.1 M6
N2  (DIS,"PROFILE MILLING")
N3  G X70 Z-5
N4  M21
N5  G0 C0 X80 S2000 M3 M8
N6  (UAV,1,XC,UV,10)
N7  (DPI,U,V)
N8  p1=U20 V0
N9  l1=p1,a90
N10 c1=I0 J35 r-25
N11 l2=U-15 V0,a-90
N12 l3=U0 V-20,a0
N13 c2=I25 J-30 r-25
N14 G21 G42 p1 F300
N15 l1
N16 r3
N17 c1
N18 r4
N19 l2
N20 r5
N21 l3
N22 r5
N23 c2
N24  r3
N25  l1
N26  G40 G20 p1
N27  (UAV,0)
N28  (DPI, Z, X)
N29  GX80
N30  M20
N99  M30
