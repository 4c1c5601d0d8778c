; A jump out of a block range that an RPT loop calls (decisions 22 and 24): the jump
; ends the range and leaves the loop around the EPP, which closes; the loop after OUT
; then runs its own two passes. Pass 1 runs A..B (X1, no jump as E1 = 0, X2), then sets
; E1 = 1, so in pass 2 the BGT in the range jumps to OUT.
; Expected: X1 X2 (the blocks themselves), X1 X2 (pass 1), X1 (pass 2), X9, X3 X3.
E1=0
"A" G0 X1
(BGT,E1,0,OUT)
"B" G0 X2
(RPT,2)
(EPP,A,B)
E1=1
(ERP)
"OUT" G0 X9
(RPT,2)
G0 X3
(ERP)
M30
