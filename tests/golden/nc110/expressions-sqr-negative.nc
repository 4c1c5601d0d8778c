; expressions-sqr-negative: SQR of a negative number is a run-time error at the block
; (§2.12; decision 10; NC4031), found by the dry run of ncc check at line 6: the value -1
; and the function SQR are named.
E30=SQR(0)
; error here
E31=SQR(E30-1)
