; branches-labels: a branch's label must be defined in its file (NC3010); a label
; is defined once per file (NC3020, with a note at the first definition)
; (§2.13.2.4 "МЕТКА" as for EPP; decision 3; decision 24). Forward and backward
; targets both count.
"A" E1=1
"A" E1=2
(BNC,NOPE)
(BEQ,E1,1,MISS)
(BGT,E1,0,A)
(BLT,E1,0,LATER)
"LATER" M30
