; parameters-overflow-run: a computed value outside the class is a run-time error
; (decision 8, NC4032) at the block; the run stops there. E30 = 300 does not fit the
; byte E7 (line 8); the message before it is shown.
E30=300
E7=E30-45
(DIS,E7)
; error here
E7=E30
(DIS,E7)
