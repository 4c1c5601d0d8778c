; NC-110 §2.8.9.3 ("if the working path is too short to accelerate and decelerate, an
; error is signalled", seed lines 4094-4095), decision 54: the stroke from R1 to the
; bottom must be at least machine.tap_min_travel (10 mm in profile cycle-tapmin).
; lines 7-8 (R2 to Z-8): a stroke of exactly 10 mm: accepted.
; lines 10-11 (R1 to Z-6): a stroke of 7 mm: NC4071 at the hole's block, line 11.
N1 S280 F315 T8.8 M6 M3
N2 G84 R2 Z-8
N3 X10
N4 G80
N5 G84 R1 Z-6
N6 X20
N7 G80
