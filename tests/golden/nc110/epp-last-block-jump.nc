; epp-last-block-jump: a range ends when its last block completes without a
; jump. If the last block jumps back into the range, the range goes on; if it
; jumps out of the range, the range ends there (decision 22; codes digest §2.5).
; 1. "B" jumps back to "A" while E1 < 3: the EPP ends with E1=3.
(BNC,GO1)
"A" E1=E1+1
"B" (BLT,E1,3,A)
"GO1" (EPP,A,B)
(DIS,E1)
; 2. "D" jumps out to OUT while E2 < 3: two EPPs end at OUT ("OUT1", "OUT2"),
; the third returns after the EPP ("END3").
(BNC,GO2)
"C" E2=E2+1
"D" (BLT,E2,3,OUT)
"GO2" (EPP,C,D)
(DIS,"NOT REACHED")
"OUT" (DIS,"OUT",E2)
(EPP,C,D)
(DIS,"END",E2)
M30
