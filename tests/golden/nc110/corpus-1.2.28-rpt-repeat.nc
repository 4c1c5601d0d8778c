; corpus-1.2.28-rpt-repeat: copy of corpus part1/1.2.28-rpt-repeat.nc (§1.2.28,
; seed L723-736: "repeat n times ... maximum 99"). The manual elides the body
; ("..........", kept as comments); a counter E30=E30+1 is supplied as the body
; and shown after the loop: (RPT,99) runs it 99 times in total (decision 20),
; expected "E30=99".
(RPT,99)
;..........
E30=E30+1
;..........
(ERP)
(DIS,E30)
