; rpt-unbalanced: an (ERP) without its (RPT) and an (RPT) without its (ERP) in a
; file are static errors (NC3021) (§2.13.2.1; decision 20; codes digest §2.3).
; ERP with no open RPT
(ERP)
E30=1
; RPT never closed before the end of the file
(RPT,2)
E31=1
