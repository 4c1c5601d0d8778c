; Copy of corpus part4/2.13.5.2-DTL-example.nc (NC-110 §2.13.5.2, seed line 9414) as
; printed, with the sentence's full stop after the block.
; Checks: the text after the closing parenthesis is an error at the '.' (line 5,
; column 15); the corrected copy is corpus-2.13.5.2-DTL-example.
(DTL,Z.1,X.05).
