; translate-gtl: a GTL profile (§2.11) into ISO. Structured translation refuses GTL
; once, at its first block, with the count of the others, and points at --flatten
; (translate-gtl.flat: the path a run makes, the tool centre's, as ISO moves).
l1 = X0 Y0, a0
l2 = X40 Y0, a90
c1 = I20 J20 r20
N1 T1.1 M6
N2 S1000 M3 F200
N3 G X-10 Y-10
N4 G21 G42 c1
N5 l1
N6 l2
N7 c1
N8 G20 G40 l1
N9 G X-10 Y-10 M30
