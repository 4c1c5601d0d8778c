; Table 2.4 (G congruence in one block), row G70: `ncc check` pairs G70 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1967): G70 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G70: f. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G70 itself (5):
G70 G17
G70 G18
G70 G19
G70 G70
G70 G71
; Compatible: no cell says 1 and not one class, no error (37):
G70 G00
G70 G01
G70 G06
G70 G02
G70 G03
G70 G33
G70 G34
G70 G27
G70 G28
G70 G29
G70 G21
G70 G20
G70 G40
G70 G41
G70 G42
G70 G80
G70 G81
G70 G82
G70 G83
G70 G84
G70 G85
G70 G86
G70 G89
G70 G90
G70 G91
G70 G79
G70 G04
G70 G09
G70 G72 X10 E40
G70 G73 r5 E40
G70 G74 X10 E40
G70 G93
G70 G94
G70 G95
G70 G96
G70 G97
G70 G35
