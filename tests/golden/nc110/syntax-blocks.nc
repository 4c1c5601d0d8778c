; syntax-blocks: the four block types of §2.5 (seed L1500-1545) and how ncc tells them
; apart (docs/dialects/nc110.md "Reading a program", decision 6): a block whose first
; character is ';' is a comment (not executed, not shown); after the leading fields a
; block starting with '(' is a three-letter code, one holding '=' outside quotes an
; assignment, any other an ISO block. The lexer runs in the mode of the block type.
;ЭТО – ПРИМЕР
; ISO block (L1524): linear X500 Y20 at F200
G1 X500 Y20 F200
; assignment blocks (L1534, L1536): an E parameter and a system variable
E30 = 28.5
(DIS,E30)
UOV=1.5
(DIS,UOV)
; a '=' inside quotes does not make an assignment: a code block, message A=B
(DIS,"A=B")
; ISO mode reads one-letter addresses: XYZ 5 is X (0), Y (0) and Z5; rapid X0 Y0 Z5
G0 XYZ 5
; assignment mode reads names: TMR is one name, not T M R; the G4 dwells 2 s
TMR=2
G4
; a label-only block and an empty '/' block do nothing
"L1"
/
M30
