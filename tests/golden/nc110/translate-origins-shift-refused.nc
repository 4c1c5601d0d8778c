; translate-origins-shift-refused: ISO's G52 shifts the work offset in force, so a
; temporary origin on another origin is refused (UOT,2 under UAO,1); in a repeat
; the incremental origin adds to a shift the text does not know (UIO in RPT)
(UAO,1)
(UOT,2,X10)
(RPT,2)
(UIO,X5)
G0 X0
(ERP)
M30
