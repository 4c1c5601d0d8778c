; CTL (NC-110 §2.13.5.4, seed lines 9487-9506); decision 36: (CTL,T) selects the turning
; configuration, whose plane is machine.turning_plane; (CTL) milling, the plane XY.
; Profile frame-turning: turning_plane = "ZX".
; Checks:
; - (CTL,T): configuration turning and plane ZX; G2 from Z10 X5 to Z0 X15 about Z0 X5
;   is clockwise in ZX (from +Z towards -X), sweep 270;
; - (CTL): configuration milling and plane XY;
; - G18 then (CTL,T): the plane is already ZX, so no plane event; G17 then (CTL): the
;   plane is already XY, no plane event.
F100
(CTL,T)
G0 Z10 X5
G2 Z0 X15 I0 J5
G0 X0
(CTL)
G18
(CTL,T)
G17
(CTL)
