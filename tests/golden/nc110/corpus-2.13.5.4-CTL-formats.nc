; Copy of corpus part4/2.13.5.4-CTL-formats.nc (NC-110 §2.13.5.4, seed lines 9499-9503
; and 16364-16366). The annotations after " - " are dropped. Corrected: the operand is
; printed with the Cyrillic letter Т; here the Latin T (the printed form is
; corpus-2.13.5.4-CTL-formats-as-printed). Both annotations say "milling"; decision 36
; reads the first as the turning configuration (the title: "lathe or milling").
; Profile frame-turning: machine.turning_plane = "ZX".
; Checks (decision 36): (CTL, T) selects the turning configuration and its plane ZX;
; (CTL) returns to milling and the plane XY.
(CTL, T)
(CTL)
