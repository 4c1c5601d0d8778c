; cls-two-levels: a called program may call another one, which may call no
; further: two calls open (§2.13.2.2 L8452-8455; §1.2.31 L818; decision 21).
; main -> FLOWC -> FLOWD: two levels, allowed. E31 and E32 count the runs.
N1 (CLS,FLOWC)
N2 (CLS,FLOWC)
N3 (DIS,E31,E32)
N4 M30
