; Words the reader explains (§2.4.5, Table 2.8, §2.7.1, §2.12; decisions 2, 14, 16):
; N1 a bare E has no number: NC2020 (the machine's E0 to E999); N2 Q is not an axis of
; this machine (nc110.axes XYZABCUVW): NC2021; N3 an expression in a word: NC2022, which
; says to compute it in an assignment; N4 a lower-case e for an E parameter: NC2019 with
; the hint; N5 RMN10: axis q 0 does not exist (RMNpq, p 1..5, q 1..9): NC3030; N6 JOG is
; a keyboard command a program cannot read: NC3029.
N1 G0 X10 E
N2 G0 Q10
N3 G1 X(E30+1) F100
N4 e1=5
N5 E1=RMN10
N6 E2=JOG
M30
