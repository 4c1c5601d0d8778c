; branches-jump-out: a jump from an RPT body to a block outside the loop closes
; the loop (and every loop it leaves); a jump inside the body keeps it (decision
; 24; codes digest §2.2). If a left loop stayed open, the next ERP would close
; the wrong loop and the counts below would differ.
; 1. leave the inner loop after its first pass, each outer pass: E30=3 E31=3 E32=3
(RPT,3)
E30=E30+1
(RPT,5)
E31=E31+1
(BNC,NEXT)
(ERP)
"NEXT" E32=E32+1
(ERP)
(DIS,E30,E31,E32)
; 2. leave backwards to before the loop while E1 < 6: 5 first passes, then the
; last loop runs its 4 passes: E1=6 E33=9
"TOP" E1=E1+1
(RPT,4)
E33=E33+1
(BLT,E1,6,TOP)
(ERP)
(DIS,E1,E33)
; 3. a jump inside the body, onto its ERP block, keeps the loop: E34=3 E35=1
(RPT,3)
E34=E34+1
(BNE,E34,2,CONT)
E35=E35+1
"CONT" (ERP)
(DIS,E34,E35)
; 4. a jump to the RPT block itself leaves the loop and starts it again:
; passes with E2 = 1, 2, 3 start it anew, then its second pass: E2=4 E36=4
"AGAIN" (RPT,2)
E2=E2+1
E36=E36+1
(BLT,E2,3,AGAIN)
(ERP)
(DIS,E2,E36)
; 5. leave two loops at once, three levels deep, from the innermost body:
; each of the 2 outer passes runs the innermost body once: E37=2 E38=2
(RPT,2)
(RPT,3)
(RPT,4)
E37=E37+1
(BNC,OUT2)
(ERP)
(ERP)
"OUT2" E38=E38+1
(ERP)
(DIS,E37,E38)
M30
