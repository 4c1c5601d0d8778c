; The G words come first: §2.8 (seed lines 1896-1899: G "must be programmed after the block number
; (if any) and before any operand of the block"). A G word after any other word of an ISO block is
; NC3012 at the G word, naming the word before it (as written). Leading fields (/, label, N) are not
; operands. Each block's codes are compatible (Table 2.4), so NC3012 is the only error.
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
; G words first, after the leading fields: no error.
N10 G01 X10 F100
/"LAB" N20 G G90 X1
; After an axis word, a bare axis, an axis with an E parameter.
X10 G01
X G01
XE30 G01
; After F, S, M (constant and E parameter), H, R, I J, the time word t.
F100 G94
S100 G97
M3 G00
ME3 G00
H5 G01
R5 G01
I5 J5 G02
t2 G01
; The implicit form GE1 after an operand (decision 15).
X10 GE1
; After the result word E of a measuring block (G72 and G00 are compatible).
G72 X10 E40 G00
; After the block number and leading fields, the columns move.
N30 X10 G01
"L2" N40 G90 X10 Y10 G01
