; NC-110 §2.8.9.3 2) (seed lines 4104-4119), decision 54: the pitch K of G84 needs a
; spindle encoder; on a machine without one (profile cycle-noencoder) the K word of the
; cycle's block is refused (NC4067, at K, 6:16), once: the refused cycle does not
; report the same again at the hole N3.
N1 S280 F315 T8.8 M6 M3
N2 G84 R7 Z-15 K1
N3 X10
N4 G80
