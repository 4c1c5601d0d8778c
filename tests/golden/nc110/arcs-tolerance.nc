; The radius check (§2.8.1.4 L2373: "if the start and end radius differ by more than
; 0.01 mm, «Профиль не конгруэнтен» is shown and the arc is not run"; decision 39: the
; tolerance is nc110.arc_tolerance, 0.01 mm by default). G29: no G27 profile rule.
; N2 end radius 10.015 against 10: 0.015 apart.
; Default (.out): NC4003 "arc end point is not on the circle: start radius 10, end radius
; 10.015, difference 0.015 exceeds the tolerance 0.01" (10:1); the run stops there.
; Profile motion-arctol (0.02, .arctol.out): the arc runs, clockwise 270 deg about X0 Y0
; with the radius of the start, 10.
N1 G29 G0 X10 Y0
N2 G2 X0 Y10.015 I0 J0 F100
