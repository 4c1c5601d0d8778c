; M30 resets the mixed codes' state (NC-110 §2.7.8 line 1873; §2.13.5.3 L9459: DLO is
; cancelled by RESET; §2.13.5.5 L9542: zones too; §2.13.5.4 L9506: RESET restores the
; milling configuration); decision 25: "no limits or zones", the power-on state.
; Profile frame-turning: machine.turning_plane = "ZX".
; Checks: at M30, as for the origin and the transform (reset-m30), the trace shows
; the state RESET restores: configuration milling (and plane XY), zone 1 off, the
; working limits cancelled, the machine's in-position tolerance on X.
(DLO,X-300 X300)
(DSA,1,X50 X60,Y50 Y60)
(ASC,1)
(DTL,X0.5)
(CTL,T)
M30
