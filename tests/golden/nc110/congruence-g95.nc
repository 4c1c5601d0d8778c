; Table 2.4 (G congruence in one block), row G95: `ncc check` pairs G95 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; G95 has no row or column in Table 2.4 (decoded in Table 2.2): ncc gives it the row of its
; classmates G93/G94/G97 (incompatible with G17-G19 only), plus the class rule.
; Class of G95: l. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible only by the class rule / ncc's rows for G95 G96 (no printed cell says 1) (6):
G95 G17
G95 G18
G95 G19
G95 G93
G95 G94
G95 G95
; Compatible: no cell says 1 and not one class, no error (36):
G95 G00
G95 G01
G95 G06
G95 G02
G95 G03
G95 G33
G95 G34
G95 G27
G95 G28
G95 G29
G95 G21
G95 G20
G95 G40
G95 G41
G95 G42
G95 G70
G95 G71
G95 G80
G95 G81
G95 G82
G95 G83
G95 G84
G95 G85
G95 G86
G95 G89
G95 G90
G95 G91
G95 G79
G95 G04
G95 G09
G95 G72 X10 E40
G95 G73 r5 E40
G95 G74 X10 E40
G95 G96
G95 G97
G95 G35
