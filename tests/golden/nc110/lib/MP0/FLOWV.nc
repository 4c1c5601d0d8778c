; FLOWV (cls-rpt-levels): three RPT levels of its own, and a label "L" that the
; main program also defines. E30 counts entries to L; the innermost body adds 1
; to E31 2*2*2 = 8 times a pass; the branch repeats the pass while E30 < 2.
"L" E30=E30+1
(RPT,2)
(RPT,2)
(RPT,2)
E31=E31+1
(ERP)
(ERP)
(ERP)
(BLT,E30,2,L)
