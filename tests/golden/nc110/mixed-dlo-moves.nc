; DLO and the moves of canned cycles and G79 (NC-110 §2.13.5.3, §1.2.39: "every motion
; ... is checked before it starts"); decision 34: every move, each checked before it
; starts.
; Checks:
; - origin X50 (UOT), limits X -100..100 from it (machine -50..150); G79 X140 is machine
;   X140 (X90 from the origin): allowed;
; - limits Z -20..50: the G81 hole at X20 to Z-15 is allowed; the hole at X30 to Z-25:
;   the rapid to X30 at Z2 is allowed and runs, the feed to Z-25 is NC4059 before it
;   starts.
F100
(UOT,0,X50)
(DLO,X-100 X100)
G79 X140
(DLO,Z-20 Z50)
G0 X10 Y0 Z10
G81 R2 Z-15
X20
X30 Z-25
