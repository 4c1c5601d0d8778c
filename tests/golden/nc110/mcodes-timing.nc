; The M codes of Table 2.3 (seed L1773-1870) and when they act in a block with motion:
; M03 M04 M07 M08 M13 M14 M19 at the start (before the move), M00 M01 M05 M06 M09 at the
; end (after it); M02 ends the program after its move. Only rapids: no G27 profile.
; M05 also switches the coolant off (§2.7.8); M13/M14 are the spindle with coolant; M19 an
; oriented stop (angle 0); M01 is skipped with the optional-stop switch off (USO 0).
; Expected per block: N1 cw, mist, rapid; N2 rapid, stop, coolant off; N3 ccw, flood,
; rapid; N4 rapid, coolant off; N5 cw + flood, rapid; N6 orient 0, rapid; N7 ccw + flood,
; rapid; N8 rapid, stop program; N9 rapid, stop optional_skipped; N10 select 1, rapid,
; tool_change 1 (T1 = corrector 0: no length event); N11 rapid, spindle stop, coolant
; off, end program.
N1 G0 X10 M3 M7
N2 X20 M5
N3 X30 M4 M8
N4 X40 M9
N5 X50 M13
N6 X60 M19
N7 X70 M14
N8 X80 M00
N9 X90 M01
N10 T1 X100 M06
N11 X110 M02
