; translate-origins-shift: NC-110's temporary and incremental origins (UOT, UIO) as
; ISO's local shift G52 of the work offset in force (profile frame-origins: origin 1
; is X100 Y200 Z-50). Expected in machine coordinates: X110 Y210 Z-45; after
; (UOT,1,X10,Y-20) X120 Y190; after (UIO,X5) twice the shift of X is 20: X130; (UAO,1)
; ends the shifts: X110 Y210, written G54 and then G52 X0 Y0.
(UAO,1)
G0 X10 Y10 Z5
(UOT,1,X10,Y-20)
G0 X10 Y10
(UIO,X5)
(UIO,X5)
G1 X10 F100
(UAO,1)
G0 X10 Y10
M30
