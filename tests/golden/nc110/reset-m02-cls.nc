; M02 in a called program (NC-110 §2.13.2.2, §2.7.8); decisions 21 and 25: M02 and M30
; end the whole run and reset the control, also inside a program called with CLS.
; Checks: RESETA (lib/MP0) runs once: G0 X10, rotation 45, origin X5, then at its
; M02 spindle stop, coolant off, origin 0, no transform, "end program"; the caller's
; G0 X20 never runs.
(CLS,RESETA)
G0 X20
M30
