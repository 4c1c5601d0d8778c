; cls-m02: M02 ends the run (decision 25: "M02 and M30 end the run"), also in a
; program that called others: expected FLOWA's message and move, N2's move and
; the end of the program, and nothing after.
N1 (CLS,FLOWA)
N2 G X0
N3 M02
