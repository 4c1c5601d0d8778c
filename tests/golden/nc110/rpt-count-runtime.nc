; rpt-count-runtime: a count from a BY parameter is checked when the RPT block
; runs: 0..99 (§2.13.2.1 L8354-8360; decision 20). E1 = 100 fits the BY class
; (0..255) but not the count: NC4045 at the RPT block, after the first loop ran.
E1=2
(RPT,E1)
E30=E30+1
(ERP)
(DIS,E30)
E1=100
N10 (RPT,E1)
E31=1
(ERP)
(DIS,"NOT REACHED")
