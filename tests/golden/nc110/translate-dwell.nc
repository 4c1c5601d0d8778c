; translate-dwell: NC-110's dwells into ISO: (DLY,t) is G04 P t; G04 dwells at the end of its block
; for the time in TMR (seconds under G94), so after the block's move
G94 G01 X10 F100
(DLY,2)
TMR=1.5
G04 X20
X30
G04
M02
