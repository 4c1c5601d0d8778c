; cls-labels: a jump stays in its file (decision 24); a label of the calling
; program is not defined in the called one: NC3010 in FLOWL. "L" is defined in
; both files, which is no duplicate (decision 3: unique in its file).
"L" (CLS,FLOWL)
"MAIN" M30
