; Table 2.4 (G congruence in one block), row G79: `ncc check` pairs G79 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1972): G79 0 0 0 0 1 1 1 1 1 1 1 0 0 0 0 1 1 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G79: i. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G79 itself (22):
G79 G17
G79 G18
G79 G19
G79 G21
G79 G20
G79 G40
G79 G41
G79 G42
G79 G80
G79 G81
G79 G82
G79 G83
G79 G84
G79 G85
G79 G86
G79 G89
G79 G90
G79 G91
G79 G79
G79 G72 X10 E40
G79 G73 r5 E40
G79 G74 X10 E40
; Compatible: no cell says 1 and not one class, no error (20):
G79 G00
G79 G01
G79 G06
G79 G02
G79 G03
G79 G33
G79 G34
G79 G27
G79 G28
G79 G29
G79 G70
G79 G71
G79 G04
G79 G09
G79 G93
G79 G94
G79 G95
G79 G96
G79 G97
G79 G35
