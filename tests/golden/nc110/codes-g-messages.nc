; G-word diagnostics and how they name the words involved. Rules: §2.8 (seed lines 1894-1904: the
; G words come first; several G only if congruent, Table 2.4), decision 4 (a bare G is G00),
; decision 11 (T is tool.corrector).
; The first block ends the run (M30): the dry run executes none of the blocks below.
M30
; NC3012 at the G names the T word before it as written: "G01 follows T1", "T1.2", "TE14.E15",
; "G00 follows T1.10".
T1 G01
T1.2 G01
TE14.E15 G01
T1.10 G00
; A G after an operand is NC3012 even when another G stands before it; each names the operand
; before the G words ("G90 follows X10", "G02 follows Y10"); line 15 is also NC3013 (class a).
X10 G01 G90
X10 Y10 G01 G02
; A bare G (G00, decision 4) is named G00 in NC3013: "G00 and G1 must not be in one block" at
; the G1 (column 3), the note "G00 is here" at the bare G (column 1).
G G1 X10
