; cls-return-eof: a called program returns at the end of its file, and the main
; program ends at the end of its file when it has no M02/M30 (decision 21: "a
; called program returns at its end"; codes digest §2.2: "end of file at level 0:
; end of program"). Expected: FLOWA's message and move once, then "DONE".
N1 (CLS,FLOWA)
N2 (DIS,"DONE")
