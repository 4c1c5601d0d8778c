; G18 is the ZX plane (decision 40; Table 2.2 "ZX (3-1)", §1.2.13, Fig. 2.5; nc110-motion.md
; T-G18): I is the Z of the centre, J the X; G02/G03 are seen from +Y, G03 turning from
; +Z towards +X. G29: no G27 profile rule.
; N2 from X0 Z0, G2 X20 Z0 I5 J10: centre Z5 X10, radius 11.1803 at both ends, clockwise
;   126.8699 deg (through X10 Z-6.1803); 24.7566 mm at F100 = 14.85396 s.
;   (Read as XZ, I5 J10 would be X5 Z10: radii 11.18 and 18.03, an error.)
; N4 G3 the other way round: 233.1301 deg (through X10 Z16.1803).
; N7 G91 from X2 Z3: X20 Z0 I5 J10 relative to the start: end X22 Z3, centre Z8 X12,
;   counter-clockwise 233.1301 deg.
N0 G29
N1 G18
N2 G2 X20 Z0 I5 J10 F100
E25 = TIM0
(DIS,E25)
N3 G0 X0 Z0
N4 G3 X20 Z0 I5 J10
N5 G0 X2 Z3
N7 G91 G3 X20 Z0 I5 J10
