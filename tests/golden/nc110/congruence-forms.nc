; Table 2.4 check (NC3013) on the written forms of G words and on blocks of several codes.
; Rules: §2.8 (seed lines 1894-1904): G and at most two digits (G1 = G01), the G words come first,
; several G in a block only if congruent; §2.4.4 leading fields; blanks between tokens (nc110.md
; "Reading a program"); decision 1 (either cell, or one class). Each G code is checked against the
; codes before it in the block and the first incompatible one is named: the error stands at the
; later code, as written (G1, G 72 shown as G72), the note at the earlier one.
; The first block ends the run (M30): the dry run executes none of the blocks below, so the report
; holds only the static checks (blocks after M30 are still read and checked, decision 25, §2.15).
M30
; One digit: G1 is G01 (class a), G2 is G02: one class, incompatible (row G01 column 02 03 = 1).
G1 G2
; G1 G90: G01 row column 90 91 = 0, G90 row column 01 = 0: compatible.
G1 G90 X10
; Blanks inside G words; G72 row column 01 = 1 (the G01 row says 0: asymmetric pair).
G 72 G 1 X10 E40
; After the leading fields: block number, skip and label; the columns move with them.
N10 G01 G00
/"LAB" N20 G17 G90
N30 G90 G91
; Three codes: G01 and G02 are both checked against G00 (first code) and both named with it.
G00 G01 G02
; G90 is compatible with G00 and G01; G01 conflicts with G00 only.
G90 G00 G01
; The same code twice (one class): G00 against G01 at column 5, the second G01 against the first.
G01 G00 G01
; Two separate conflicts in one block: G91 against G90, G01 against G00.
G90 G91 G00 G01
; G17 (a plane code) is incompatible with every code in Table 2.4 (its row and column are all 1):
; in G90 G70 G17 the first code G17 conflicts with is G90.
G90 G70 G17
; Compatible sets of six codes (no two share a class, no cell says 1): no error.
G00 G90 G94 G97 G71 G29 X10
G01 G91 G95 G96 G70 G28 X10 F1
; The same with G09 added: the G09 row has 1 in column 27 28 (the G28 row has 0 in column 09).
G01 G91 G95 G96 G70 G28 G09 X10 F1
; A measuring code with its E word and the codes it admits (G72 row: G00, G90 G91, G70 G71 are 0).
G72 G00 G91 G71 X10 E40
