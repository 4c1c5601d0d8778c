; memory-branch: memory values checked by branching (§2.13.2.4, Table 2.10 L8552) rather
; than DIS (decision 17 layout, decision 23 exact comparison). Every branch below is
; taken; a "WRONG" message would show one that is not. The messages OK 1..OK 5 show.
; SYVAR1.IN = 268 (L5104) = 0x010C at bytes 2-3: byte 2 = 12, byte 3 = 1
SYVAR1.IN = 268
(BEQ,SYVAR1.IN,268,L1)
(DIS,"WRONG 1")
"L1" (DIS,"OK 1")
(BEQ,SYVAR2.BY,12,L2)
(DIS,"WRONG 2")
"L2" (DIS,"OK 2")
; bit 0 of byte 3 (bit 24) is 1, bit 25 is 0
(BGT,SYVAR24.BL,SYVAR25.BL,L3)
(DIS,"WRONG 3")
"L3" (DIS,"OK 3")
; a text (L8585 (BEQ,SYVAR1.2CH,"OK",LAB1)); "OK" is at bytes 1-2, over byte 2
SYVAR1.2CH="OK"
(BEQ,SYVAR1.2CH,"OK",LAB1)
(DIS,"WRONG 4")
"LAB1" (DIS,"OK 4")
; "K" is ASCII 75: SYVAR2 = 75 now, and SYVAR1.IN = 75 + 256*1 = 331
(BNE,SYVAR1.IN,331,WRONG)
(BEQ,SYVAR2,75,L5)
"WRONG" (DIS,"WRONG 5")
"L5" (DIS,"OK 5")
