; corpus-1.2.20-dis-messages: copy of corpus part1/1.2.20-dis-messages.nc
; (§1.2.20, seed L612-617). The manual: show (1) the text ИНСТРУМЕНТ=12,
; (2) the value of E37, (3) the value of the system variable UOV.
; Expected (decision 37): messages "ИНСТРУМЕНТ=12", "E37=0", "UOV=0" (E
; parameters and UOV are 0 at the start, decision 8).
; Changed: the manual's «» quotes are the ASCII " of Table 2.1 (as in the corpus
; copy); the corpus' comment lines are shortened into this header.
(DIS, "ИНСТРУМЕНТ=12")
(DIS, E37)
(DIS, UOV)
