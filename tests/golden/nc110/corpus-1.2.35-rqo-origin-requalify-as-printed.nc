; Copy of corpus part1/1.2.35-rqo-origin-requalify.nc (NC-110 §1.2.35, seed line 943) as
; printed: (RQO,O,XE35) has the Latin letter O where the digit 0 is meant.
; Checks (decision 19): the letter O is an error with a hint at the operand (NC3018),
; line 5 column 6. The corrected copy is corpus-1.2.35-rqo-origin-requalify.
(RQO,O,XE35)
