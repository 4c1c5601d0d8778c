; epp-jump-inside: a jump from a block of a running range to another block of
; the same range keeps the range: it still ends after its last block and
; returns after the EPP (decision 22; codes digest §2.2: only a target outside
; the range ends it). In sequence: E1=1, the jump skips E2; through the EPP the
; same: E1=2, E2 unchanged, then "AFTER" with E3=2.
"A" E1=E1+1
(BNC,IN)
E2=E2+1
"IN" E3=E3+1
"B" (DIS,E1,E2,E3)
(EPP,A,B)
(DIS,"AFTER")
M30
