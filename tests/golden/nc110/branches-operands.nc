; branches-operands: VAR1 and VAR2 may be E parameters, constants, PLC signals
; SA/SK, SYVAR and readable system variables (§2.13.2.4 L8565-8569; seed example
; N20 (BEQ,SA3,1,LAB1): "the boolean SA3 is on"; decision 23). Memories start at
; 0 (decision 17). A message shows only when a branch is NOT taken.
; SA3 is bit 3 of SA (BL by default): 0 at the start -> not taken
(BEQ,SA3,1,A1)
(DIS,"SA3 IS 0")
"A1" SA3=1
(BEQ,SA3,1,A2)
(DIS,"SA3 NOT 1")
; SA0.BY holds bits 0-7: bit 3 set -> 8
"A2" (BEQ,SA0.BY,8,A3)
(DIS,"SA0.BY NOT 8")
; SK is bytes (BY by default)
"A3" SK10=200
(BGT,SK10,199,A4)
(DIS,"SK10 NOT GT 199")
; SYVAR: IN at bytes 4-5 against the BY byte 0
"A4" SYVAR2.IN=-300
(BLT,SYVAR2.IN,SYVAR0,A5)
(DIS,"SYVAR2.IN NOT LT")
; SYVAR LR at bytes 16-23 against an LR parameter
"A5" SYVAR2.LR=12.5
E30=12.5
(BEQ,SYVAR2.LR,E30,A6)
(DIS,"SYVAR2.LR NE E30")
; system variables: UOV, TMR, RMS (100 at power-on), USB (1), TIM0 (the clock)
"A6" UOV=0.5
(BEQ,UOV,0.5,A7)
(DIS,"UOV NE 0.5")
"A7" TMR=2
(BGE,TMR,2,A8)
(DIS,"TMR NOT GE 2")
"A8" (BEQ,RMS,100,A9)
(DIS,"RMS NE 100")
"A9" (BEQ,USB,1,A10)
(DIS,"USB NE 1")
; one second of dwell: TIM0 reads 1 after it
"A10" (DLY,1)
(BEQ,TIM0,1,A11)
(DIS,"TIM0 NE 1")
"A11" (DIS,"END")
M30
