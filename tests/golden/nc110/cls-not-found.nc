; cls-not-found: a called program that is not in the library is an error at the
; CLS operand (NC3027), statically and before the run (decision 21), once: its
; second call (N4) has errors too and says nothing more.
N1 (CLS,FLOWA)
N2 (CLS,FLOWX)
N3 (CLS,FLOWA/MP7)
N4 (CLS,FLOWX)
N5 M30
