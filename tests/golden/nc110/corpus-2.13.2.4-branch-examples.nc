; corpus-2.13.2.4-branch-examples: copy of corpus part4/2.13.2.4-branch-
; examples.nc (§2.13.2.4, seed L8577-8585 / L15849-15852), the branch blocks
; alone. Their labels END, LAB1 and START are not defined in the fragment.
; Expected (ncc check): NC3010 at END (N10), LAB1 (N20), START (N30) and LAB1
; (N40); the operands themselves are valid.
; Changed: the manual's annotations after the blocks are dropped.
N10 (BGT,E1,123,END)
N20 (BEQ,SA3,1,LAB1)
N30 (BNE,E1,E5,START)
N40 (BEQ,SYVAR1.2CH,"OK",LAB1)
