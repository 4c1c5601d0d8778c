; NC-110 §2.17.1.2 (seed lines 10930-10970, figure 2.145), decision 83: a profile on
; a plane milled with C and X through the virtual axes U V (mode 1, polar). Profile uav:
; corrector 1 radius 5, C's rapid 800 degrees/min.
; E40 = 110 * 180 / (3.14159 * 800) = 7.878176: the minimum radius for F110 (formula
;   2.7, as the manual's note writes it).
; (UAV,1,XC,UV,E40) at X80 C0: U80 V0. The profile, programmed: U20 V0, V20 (fillet
;   r3), U-15 (chamfer b5), V-20 (fillet r5), U0 V-20, then the arc G2 to U20 V0 about
;   I20 J-20 (radius 20). It keeps outside 7.878: the lines pass 15 from the centre at
;   the nearest (U-15 V0); the arc comes nearest at its middle, 20 * sqrt(2) - 20 =
;   8.2843 from it.
; (UAV,0) at U20 V0: X = 20, and C has turned a whole turn counter-clockwise with the
;   profile: C360 (the angle of U20 V0 after going round the centre once).
; GX80 then moves X from 20 to 80; the trace shows U V as they were before (0).
T0.1 M6
GX30 Z-5
E40=110*180/(3.14159*800)
M21
GC0 X80 S1000 M3 M8
(UAV, 1, XC, UV, E40)
(DPI, U, V)
G1 G42 U20 V F110
V20
r3
U-15
b5
V-20
r5
U0
G40 G2 U20 V0 I20 J-20
(UAV, 0)
GX80
M20
M30
