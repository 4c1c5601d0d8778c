; epp-nested-runtime: an EPP met while a range runs is a run-time error (NC4046)
; (§2.13.2.3 L8531-8532; decision 22). The inner EPP is in FLOWE, called from the
; range A..B. Called in sequence first, FLOWE's own EPP runs (E5=2, E6=2); called
; again inside the range run by N4, it fails at FLOWE line 4 col 1. ncc check follows
; the call (decision 21) and reports the same error there (.check.out).
"A" N1 (CLS,FLOWE)
"B" N2 (DIS,E5,E6)
N4 (EPP,A,B)
N5 (DIS,"NOT REACHED")
N6 M30
