; Table 2.4 (G congruence in one block), row G96: `ncc check` pairs G96 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; G96 has no row or column in Table 2.4 (decoded in Table 2.2): ncc gives it the row of its
; classmates G93/G94/G97 (incompatible with G17-G19 only), plus the class rule.
; Class of G96: m. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible only by the class rule / ncc's rows for G95 G96 (no printed cell says 1) (5):
G96 G17
G96 G18
G96 G19
G96 G96
G96 G97
; Compatible: no cell says 1 and not one class, no error (37):
G96 G00
G96 G01
G96 G06
G96 G02
G96 G03
G96 G33
G96 G34
G96 G27
G96 G28
G96 G29
G96 G21
G96 G20
G96 G40
G96 G41
G96 G42
G96 G70
G96 G71
G96 G80
G96 G81
G96 G82
G96 G83
G96 G84
G96 G85
G96 G86
G96 G89
G96 G90
G96 G91
G96 G79
G96 G04
G96 G09
G96 G72 X10 E40
G96 G73 r5 E40
G96 G74 X10 E40
G96 G93
G96 G94
G96 G95
G96 G35
