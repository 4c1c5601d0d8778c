; Origin 0 declared in the profile for some axes only (NC-110 §2.13.1.1: "(UAO,0)
; activates origin 0 for all axes"; "after power-on and RESET origin 0 is active for all
; axes"); decisions 25 and 30.
; Profile frame-origin0: origin 0 = X10 Y20 (no Z); origin 1 = X100 Y200 Z-50.
; Checks: (UAO,1), then (UAO,0) selects origin 0 on every axis, as RESET does: X10 Y20
; Z0 (Z of origin 0 is 0, not origin 1's -50); G0 Z0 goes to machine Z0.
(UAO,1)
(UAO,0)
G0 Z0
M30
