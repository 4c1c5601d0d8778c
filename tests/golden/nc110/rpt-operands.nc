; rpt-operands: the count of (RPT,n) is a whole constant 0..99 or one BY parameter
; E0-E9 (§2.13.2.1 L8354-8360, Table 2.9; decisions 14, 19, 20); (ERP) takes none.
; Each loop below is balanced: only its operand is wrong.
; 100 is over the range: NC3018
(RPT,100)
(ERP)
; not a whole number: NC3018
(RPT,1.5)
(ERP)
; negative: NC3018
(RPT,-1)
(ERP)
; IN and LR parameters are not BY: NC2016
(RPT,E10)
(ERP)
(RPT,E30)
(ERP)
; no count: NC3016; two operands: NC3017
(RPT)
(ERP)
(RPT,2,3)
(ERP)
; an expression: NC3018
(RPT,E1+1)
(ERP)
; ERP with an operand: NC3017
(RPT,2)
(ERP,1)
