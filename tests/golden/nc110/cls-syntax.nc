; cls-syntax: (CLS,NAME[/DEV]): NAME is 1 to 6 capitals and digits, a letter
; first; DEV 2 or 3 capitals and digits, a letter first; never quoted, never an E
; parameter or a second operand (§2.13.2.2 L8428-8432 "only capitals, the first a
; letter"; three_letter_codes.tsv "program"). Each line is one error.
(CLS,flowa)
(CLS,1FLOW)
(CLS,FLOWAB7)
(CLS,FLOWA/mp0)
(CLS,FLOWA/M)
(CLS,FLOWA/MP00)
(CLS,FLOWA/0MP)
(CLS,FLOWA/)
(CLS,"FLOWA")
(CLS)
(CLS,FLOWA,MP0)
M30
