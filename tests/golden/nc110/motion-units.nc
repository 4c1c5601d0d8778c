; Inches and millimetres (§2.8.8, G70/G71). Under G70 lengths and F are in inches
; (in/min); the trace shows program units; the arc tolerance stays 0.01 mm (decision 39,
; nc110.arc_tolerance; 0.01 mm = 0.0004 in shown).
; N2 1.414214 in at 10 in/min = 8.485281 s; N3 a quarter circle of radius 1 in, 1.570796
; in = 9.424778 s: TIM0 17.91006.
; N5 end radius 1.0003 in: 0.00762 mm off, within 0.01 mm: runs.
; N7 back to mm: N8 X25.4 Y0 is the point X1 Y0 in: a rapid event at X25.4 Y0.
; N9 G70 again: N10 end radius 1.0005 in = 0.0127 mm off: NC4003 "start radius 1, end
; radius 1.0005, difference 0.0005 exceeds the tolerance 0.0004", the run stops.
N1 G70
N2 G1 X1 Y1 F10
N3 G2 X2 Y0 I1 J0
E25 = TIM0
(DIS,E25)
N4 G0 X1 Y0
N5 G2 X0 Y1.0003 I0 J0
N6 G0 X1 Y0
N7 G71
N8 G0 X25.4 Y0
N9 G70
N10 G2 X0 Y1.0005 I0 J0
