; branches-operand-errors: the operands of a branch are VAR1, VAR2 and an
; unquoted label (BNC: the label alone); each VAR is a constant, one E parameter,
; SA/SK/SYVAR, a readable system variable or a quoted text, never an expression
; (§2.13.2.4 Table 2.10; decision 19; three_letter_codes.tsv "comparand").
"L" (BNC)
(BNC,L,L)
(BEQ,SYVAR1.2CH,"OK")
(BEQ,E1,1,"L")
(BEQ,E1,E2+1,L)
(BGT,E1,1,L,L)
(BEQ,XYZ,1,L)
(BEQ,JOG,1,L)
M30
