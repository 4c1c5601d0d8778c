; Axis operands name axes of the machine (three_letter_codes.tsv: "axis: one axis letter"; §2.13.1
; "the configured axes"): with profiles/check-xyzp.toml (axes X Y Z P), A and U are not axes and are
; NC3018 in every axis-letter, axis-value and pair operand; P (an indexing axis) is one, and takes an
; RE E parameter (Table 2.9, line 7805: "indexing axes", PE29). UAO and MIR without axes stay valid.
; The first block ends the run (M30): the dry run executes none of the blocks below.
M30
; Valid on this machine.
(UAO,1,X,P)
(MIR,Z,P)
(UOT,0,PE29,X10)
(DLO,P-90 P90)
(DPI,X,P)
; A and U are not axes of this machine.
(UAO,1,A)
(MIR,X,U)
(UIO,A10)
(DLO,U-1 U1)
(DSA,1,X1 X2,A1 A2)
(DPI,Z,A)
(BSP,X,U,0)
