; translate-dlo: DLO's pairs of values into NC-110 as written, the upper value first too
; (NC-110 §2.13.5.3); the moves stay inside the working field
(DLO,X-50 X100)
(DLO,Y100 Y-100,Z-60 Z20)
G0 X100 Y-100 Z20
G1 X-50 Y100 Z-60 F500
M30
