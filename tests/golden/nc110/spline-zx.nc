; A G06 spline in the ZX plane (G18: abscissa Z, ordinate X; decisions 40, 43): the BSP
; axes are the plane's, in its order; an axis outside the plane (Y) moves linearly per
; span, its controls at 1/3 and 2/3. Natural ends (n=0). G29: no G27 profile rule.
; Q0 = Z0 X0 (lead-in from Z-10 X0), Q1 = Z10 X10 Y5, Q2 = Z20 X0 Y10, lead-out to Z30.
; Equal chords (14.1421): Z' = 1 throughout, X' = 1.0607, 0, -1.0607 (per unit of chord):
; N6: controls Z3.3333 X5 Y1.6667 and Z6.6667 X10 Y3.3333;
; N7: controls Z13.3333 X10 Y6.6667 and Z16.6667 X5 Y8.3333.
N0 G29
N1 G18
N2 G0 Z-10 X0
N3 (BSP,Z,X,0)
N5 G1 Z0 X0 F100
N6 G6 Z10 X10 Y5
N7 Z20 X0 Y10
N8 G0 G40 Z30 X0
N9 (ESP)
