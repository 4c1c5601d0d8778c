; A WAI condition met by a text written into SYVAR (decision 63) goes on from the time it was
; written: process 2 (lib/MP0/TXTW2) writes "A" (65) at the end of its 1 s move, and process 1,
; waiting for byte 0 to be 65, goes on then (TIM0 1.0xx: the move began after two block cycles).
(WAI,SYVAR0.BY=65)
(DIS,"P1 GOES ON AT ",TIM0)
M30
