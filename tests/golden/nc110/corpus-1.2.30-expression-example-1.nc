; corpus-1.2.30-expression-example-1: copy of corpus/nc110/part1/
; 1.2.30-expression-example-1.nc (§1.2.30 seed L798). Expect: E37 = E31*SIN(E30) +
; 123.4567/SQR(16) = E31*SIN(E30) + 30.864175 (SQR the square root, usual precedence).
; With every E parameter 0 at the start: E37 = 30.864175. Changed: DIS added; a second
; run of the block after E31 = 2, E30 = 30 (supplied values): 2*0.5 + 30.864175 =
; 31.864175; then the §2.12 form (L7724) with parentheses, a different program:
; (1 + 123.4567)/4 = 31.114175.
N1 E37=E31*SIN(E30)+123.4567/SQR(16)
(DIS,E37)
E31=2
E30=30
N1 E37=E31*SIN(E30)+123.4567/SQR(16)
(DIS,E37)
N1 E37=(E31*SIN(E30)+123.4567)/SQR(16)
(DIS,E37)
