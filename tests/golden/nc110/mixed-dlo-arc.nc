; DLO with arcs (NC-110 §1.2.39: "every motion, linear or circular, is checked before it
; starts"); decision 34: arcs are checked as chords within 0.0001 mm.
; Checks:
; - with X up to 210, the half circle G3 from X190 Y0 to X190 Y40 about X190 Y20 reaches
;   X210 exactly: allowed;
; - with X up to 200, the clockwise half circle (through X170) is allowed;
; - the counter-clockwise one would reach X210: NC4059 before the move, and the message
;   gives the farthest point the move would reach, 210.
F100
G0 X190 Y0
(DLO,X50 X210)
G3 X190 Y40 I190 J20
G0 X190 Y0
(DLO,X50 X200)
G2 X190 Y40 I190 J20
G0 X190 Y0
G3 X190 Y40 I190 J20
