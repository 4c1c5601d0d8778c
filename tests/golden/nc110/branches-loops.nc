; branches-loops: a jump into an RPT body from outside the loop is a static
; error at the label operand (NC3023): forwards, backwards, onto the ERP block,
; and from one loop into another (decision 24; codes digest §2.2).
(BNC,IN1)
(RPT,2)
"IN1" E30=E30+1
"END1" (ERP)
(BEQ,E30,1,IN1)
(BNC,END1)
(RPT,2)
(BNC,IN2)
(ERP)
(RPT,3)
"IN2" E31=1
(ERP)
M30
