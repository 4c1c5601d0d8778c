; CTL on a machine without a turning configuration (NC-110 §2.13.5.4: "if both are
; installed in PGCFIL"); decision 36: NC4063.
; Checks (ncc check, default profile: no machine.turning_plane): (CTL,T) is NC4063 at
; the code; (CTL) is allowed.
(CTL,T)
(CTL)
