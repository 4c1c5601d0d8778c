; epp-jump-out: a jump from inside a running range to a block outside it ends
; the range; execution goes on at the jump's target, and a later EPP runs
; without NC4046 (decision 22: "a jump out of the range ends it"; codes digest
; §2.5). The range is A..B; its second block leaves it while E1 > 1.
(BNC,GO)
"A" E1=E1+1
(BGT,E1,1,OUT)
"B" E2=E2+1
; first EPP: A, the branch not taken, B: E1=1 E2=1 E3=0
"GO" (EPP,A,B)
(DIS,E1,E2,E3)
; second EPP: A (E1=2), the branch leaves the range for OUT
(EPP,A,B)
(DIS,"NOT REACHED")
"OUT" E3=E3+1
(BGE,E3,2,DONE)
; third EPP, after the range was left: runs, leaves again -> E1=3 E2=1 E3=2
(EPP,A,B)
"DONE" (DIS,E1,E2,E3)
M30
