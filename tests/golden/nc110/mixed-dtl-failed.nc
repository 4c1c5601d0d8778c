; A DTL that fails on one axis (NC-110 §2.13.5.2); decision 33: NC4062.
; Profile frame-tolerance: X drive error 0.5, Z 1.
; Checks (ncc run): (DTL,Z0.1,X0.6) stops the run with NC4062 at X0.6 before any
; tolerance event: the trace has no "tolerance" line (not an empty one, not Z alone).
G0 X1
(DTL,Z0.1,X0.6)
