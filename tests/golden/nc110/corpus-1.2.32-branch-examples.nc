; corpus-1.2.32-branch-examples: copy of corpus part1/1.2.32-branch-examples.nc
; (§1.2.32, seed L842-869), as printed. The fragment's labels END, LAB and
; START are not defined, and N40 writes OK without quotes against SYVAR1.CH, a
; 1-character reference (§2.13.2.4 L8588-8590), so it can never be "OK".
; Expected (ncc check): NC3010 at END (N10), LAB (N20) and START (N30), and at
; N40 the unquoted OK, which reads as a name and is no system variable (NC3028;
; one error per block: N40's END is not checked once its operand failed).
; Changed: the manual-text comment lines are dropped.
N10 (BGT,E1,123,END)
N20 (BEQ,SA3,1,LAB)
N30 (BNE,E1,E5,START)
N40 (BEQ,SYVAR1.CH,OK,END)
