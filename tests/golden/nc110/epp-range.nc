; epp-range: (EPP,L1,L2) runs the blocks from the one labelled L1 to the one
; labelled L2, both included, then goes on with the block after the EPP
; (§2.13.2.3 L8499-8531, "N150(EPP,START,END) - executes blocks N25 to N100";
; decision 22). A range may hold whole RPT loops and calls; a range that lies in
; one loop body may be run from that body.
"START" N25 G X10
N26 G X20
"END" N100 G X30
N101 (DIS,"SEQUENCE")
; N25, N26, N100 again, then N151
N150 (EPP,START,END)
N151 (DIS,"AFTER EPP")
; a range of one block: both labels the same -> N100 once more
N152 (EPP,END,END)
; a range holding a whole loop (2 runs) and a call of FLOWD (E32 + 1):
; in sequence E30=2 E32=1, through N170 E30=4 E32=2
"R1" N160 (RPT,2)
N161 E30=E30+1
N162 (ERP)
N163 (CLS,FLOWD)
"R2" N164 (DIS,E30,E32)
N170 (EPP,R1,R2)
; a range in a loop body, run from the same body: each pass runs P and Q twice
N180 (RPT,2)
"P" N181 E33=E33+1
"Q" N182 E34=E34+1
N183 (EPP,P,Q)
N184 (ERP)
N185 (DIS,E33,E34)
N186 G X0
N187 M30
