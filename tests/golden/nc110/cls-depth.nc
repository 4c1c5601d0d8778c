; cls-depth: main -> FLOWB -> FLOWC -> FLOWD would open three calls; the checker
; follows the calls into the library and reports the CLS of FLOWD in FLOWC with
; the chain (NC3025) (§2.13.2.2 L8452-8455: two levels; decision 21).
; main -> FLOWC -> FLOWD alone is allowed (cls-two-levels).
N1 (CLS,FLOWC)
N2 (CLS,FLOWB)
N3 M30
