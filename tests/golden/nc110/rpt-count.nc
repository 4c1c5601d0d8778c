; rpt-count: (RPT,n) ... (ERP) runs the blocks n times in total, n = 0..99,
; 0 skips them, the count is read when the RPT block runs (§2.13.2.1, seed
; L8354-8360; §1.2.28 L723; docs/dialects/nc110.md decision 20).
; (RPT,3): the body runs 3 times -> E30=3
(RPT,3)
E30=E30+1
(ERP)
(DIS,E30)
; (RPT,1): once -> E31=1
(RPT,1)
E31=E31+1
(ERP)
(DIS,E31)
; (RPT,0): skipped -> E32=0
(RPT,0)
E32=1
(ERP)
(DIS,E32)
; (RPT,E1) with the BY parameter E1 = 0 (all E are 0 at the start): skipped -> E33=0
(RPT,E1)
E33=1
(ERP)
(DIS,E33)
; the largest count, 99 (§1.2.28: "maximum 99") -> E34=99
(RPT,99)
E34=E34+1
(ERP)
(DIS,E34)
; the count is latched when RPT runs: the body changes E1, the loop still runs 4 times
E1=4
(RPT,E1)
E35=E35+1
E1=1
(ERP)
(DIS,E35,E1)
; an inner (RPT,E2) is read again on each entry: 1 + 2 + 3 = 6 runs, E2 ends at 4
E2=1
(RPT,3)
(RPT,E2)
E36=E36+1
(ERP)
E2=E2+1
(ERP)
(DIS,E36,E2)
; a move in the body: two G91 feeds of X10 -> X10, X20
(RPT,2)
G91 G1 X10 F100
(ERP)
G90 G X0
M30
