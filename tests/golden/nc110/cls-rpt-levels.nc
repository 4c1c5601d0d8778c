; cls-rpt-levels: the three RPT levels are counted per program file, so a program
; called from the innermost of three loops may open three of its own; labels
; belong to their file: "L" here and "L" in FLOWV are different labels
; (decision 20 "three levels per file"; decision 3; decision 24).
; FLOWV is called 2*2*2 = 8 times. First call: E30 -> 1, 8 runs, branch back,
; E30 -> 2, 8 runs; then 7 calls with 8 runs each: E30 = 9, E31 = 16 + 56 = 72.
"L" (RPT,2)
(RPT,2)
(RPT,2)
(CLS,FLOWV)
(ERP)
(ERP)
(ERP)
(DIS,E30,E31)
M30
