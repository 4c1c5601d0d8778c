; The frame's parts act independently (NC-110 §2.13.1); decisions 26, 28: UIO and UOT
; values are not scaled, mirrored or rotated; URT is absolute (§2.13.1.5: the value is
; the angle); the rotation and mirror centre is the current origin, wherever it moves;
; UAO/UOT/UIO leave the rotation, mirror and scale as they are.
; Checks:
; - (SCF,E25,X,Y) with the RE parameter E25 = 1.5: scale X1.5 Y1.5;
; - (URT,30) then (URT,90): rotation 90, not 120;
; - (UIO,X10) and (UOT,0,Y5) under scale, rotation 90 and mirror X: origin X10 Y5 as
;   written (no transform event);
; - G0 X10 Y0: (15,0) scaled, (-15,0) mirrored, X0 Y-15 rotated (machine X10 Y-10);
; - (UIO,X-10): origin X0 Y5; G0 X10 Y0 is X0 Y-15 about the new origin (machine
;   X0 Y-10).
F100
E25=1.5
(SCF,E25,X,Y)
(URT,30)
(URT,90)
(MIR,X)
(UIO,X10)
(UOT,0,Y5)
G0 X10 Y0
(UIO,X-10)
G0 X10 Y0
