; DPI (NC-110 §2.13.5.1, seed lines 9368-9395); decision 32: any two axes make the
; plane, the first the abscissa; arcs (I J = the centre's abscissa and ordinate,
; decision 39), URT (counter-clockwise from the abscissa towards the ordinate) and
; helices use it; DPI is allowed under G27/G28.
; Checks:
; - (DPI,Z,U), power-on G27: G2 from Z10 U20 to Z0 U30 about Z0 U20 is clockwise in the
;   plane ZU (from +Z towards -U), sweep 270; (URT,90) turns Z10 U0 into Z0 U10;
; - (DPI,Z,X): G3 from Z10 X0 to Z0 X10 about Z0 X0 with Y5 is a helix along Y,
;   counter-clockwise, sweep 90;
; - (DPI,Y,X), the pair the other way round: G2 from X10 Y0 to X0 Y10 about X0 Y0 is
;   clockwise in the plane YX (from +Y towards -X), sweep 90 (under G17 it would be
;   270); (URT,90) turns X10 Y0 (Y0 X10 in the plane) into Y-10 X0;
; - G28 and a feed move, then (DPI,X,Y): allowed, plane XY.
F100
(DPI,Z,U)
G0 Z10 U20
G2 Z0 U30 I0 J20
(URT,90)
G0 Z10 U0
(URT,0)
(DPI,Z,X)
G0 Z10 X0 Y0
G3 Z0 X10 I0 J0 Y5
(DPI,Y,X)
G0 X10 Y0 Z0
G2 X0 Y10 I0 J0
(URT,90)
G0 X10 Y0
(URT,0)
G28
G1 X5
(DPI,X,Y)
G0 X0 Y0
