; Copy of corpus part4/2.13.5.2-DTL-example.nc (NC-110 §2.13.5.2, seed line 9414; the
; heading misprints the code as DLT). Corrected: the full stop after the block is the
; sentence's (the printed form is corpus-2.13.5.2-DTL-example-as-printed). Added:
; (DTL,X0).
; Profile frame-tolerance: X tolerance 0.01, drive error 0.5; Z 0.02 and 1.
; Checks (decision 33): the in-position tolerance becomes 0.1 on Z and 0.05 on X (the
; event lists the axes in the machine's order); (DTL,X0) restores the machine's 0.01
; on X and leaves Z at 0.1 (no event for Z).
(DTL,Z.1,X.05)
(DTL,X0)
