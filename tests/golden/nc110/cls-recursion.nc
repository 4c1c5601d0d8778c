; cls-recursion: a program that calls itself, directly or through another, is
; reported statically (NC3026) (decision 21; §2.13.2.2 allows two levels only).
N1 (CLS,FLOWR)
N2 (CLS,FLOWS)
N3 M30
