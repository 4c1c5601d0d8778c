; rpt-nesting: three levels of RPT are allowed, a fourth is an error (NC3022)
; (§2.13.2.1, seed L8395: "up to two RPT inside another RPT"; decision 20).
; Levels 1-3: allowed.
(RPT,2)
(RPT,2)
(RPT,2)
E30=E30+1
(ERP)
(ERP)
(ERP)
; A fourth level at line 15 col 1: NC3022.
(RPT,2)
(RPT,2)
(RPT,2)
(RPT,2)
E31=E31+1
(ERP)
(ERP)
(ERP)
(ERP)
; After closing, a new three-level nest is fine again.
(RPT,1)
(RPT,1)
(RPT,1)
E32=1
(ERP)
(ERP)
(ERP)
