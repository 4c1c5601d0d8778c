; cls-m30: M02/M30 in a called program ends the whole run, not only the call
; (docs/dialects/nc110.md "Running a program": a program ends at M02 or M30;
; decision 25; codes digest §2.2). The blocks after it are not run.
N1 (CLS,FLOWZ)
N2 (DIS,"NOT REACHED IN MAIN")
N3 M30
