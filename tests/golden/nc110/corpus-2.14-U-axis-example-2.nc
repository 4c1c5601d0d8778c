; Copy of corpus part4/2.14-U-axis-example-2.nc (NC-110 §2.14, Fig. 2.137, seed lines
; 10005-10019): a GTL profile in the Z-U plane of a boring and facing head. The two
; columns of the listing are read left then right. Supplied where the manual elides
; values: N10 S500 F100; N12 (UIO,X10,Y20,Z30); N13 is printed "G X Y 8" (a letter is
; lost in both renderings): Z8 here; N29 "..." is dropped.
; Profile frame-uaxis: origin 15 and tool T20.20 of the head.
; Checks (decisions 65-70): an open GTL profile from p1 to p2 under G41 with T20.20's
; radius 0.8, with a chamfer b5 and a fillet r-15, in diameters as programmed
; (decision 75). By hand: N16 starts square to l1 (at -135 deg) on its left:
; (0.566, 185.434); l2 moved 0.8 to its left is U179.2, l3 Z-49.2, l5 U99.2; the
; chamfer from (Z-45, U180) to (Z-50, U175) moved meets U179.2 at Z-44.669 and Z-49.2 at
; U174.669; the fillet r-15 (clockwise, about Z-65 U125.062, tangent to l3 and l4) grows
; to 15.8; N24 ends square to l5 at p2: Z-100 U99.2; N25 leaves it.
N1 (DIS,".................")
N2 (DPI,Z,U)
N3 p1 = Z U186
N4 l1 = p1, a-135
N5 l2 = Z U180, a180
N6 l3 = Z-50 U, a-90
N7 l4 = Z-90 U100, a-160
N8 l5 = Z U100, a180
N9 p2 = Z-100 U100
N10 S500 F100 T20.20 M6 M3
N11 (UAO,15)
N12 (UIO,X10,Y20,Z30)
N13 G X Y Z8
N14 U190
N15 Z2
N16 G21 G41 p1
N17 l1
N18 l2
N19 b5
N20 l3
N21 r-15
N22 l4
N23 l5
N24 G20 G40 p2
N25 G U90
N26 Z2
N27 (DPI,X,Y)
N28 (UAO,0)
