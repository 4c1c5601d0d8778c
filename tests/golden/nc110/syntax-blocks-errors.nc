; syntax-blocks-errors: a block holds one instruction (§2.5, seed L1500-1545; decision 6):
; a second '=' is NC1028, reported at the second assignment (its target and the rest).
; chained assignment: error at column 4 (E2=3)
E1=E2=3
; the same after leading fields and blanks: error at column 18 (E3 = 4)
"L1" N5 SYVAR1 = E3 = 4
; a '=' inside quotes is text, not a second assignment: no error
SK1.3CH="A=B"
