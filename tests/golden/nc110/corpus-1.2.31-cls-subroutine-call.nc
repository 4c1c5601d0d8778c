; corpus-1.2.31-cls-subroutine-call: copy of corpus part1/1.2.31-cls-subroutine-
; call.nc (§1.2.31, seed L811-826): "N35 calls the stored subroutine PROG1
; (subroutine nesting at most 2 levels)". PROG1 is lib/MP0/PROG1.nc (supplied;
; the default device is MP0). Expected: PROG1's message and move, then the
; return to N36.
; Added: N36, a rapid back to X0 and M30 (the manual's fragment has no end).
N35 (CLS,PROG1)
N36 G X0 M30
