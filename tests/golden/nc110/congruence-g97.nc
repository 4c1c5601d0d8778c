; Table 2.4 (G congruence in one block), row G97: `ncc check` pairs G97 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1985): G97 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G97: m. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G97 itself (3):
G97 G17
G97 G18
G97 G19
; Incompatible only by the class rule / ncc's rows for G95 G96 (no printed cell says 1) (2):
G97 G96
G97 G97
; Compatible: no cell says 1 and not one class, no error (37):
G97 G00
G97 G01
G97 G06
G97 G02
G97 G03
G97 G33
G97 G34
G97 G27
G97 G28
G97 G29
G97 G21
G97 G20
G97 G40
G97 G41
G97 G42
G97 G70
G97 G71
G97 G80
G97 G81
G97 G82
G97 G83
G97 G84
G97 G85
G97 G86
G97 G89
G97 G90
G97 G91
G97 G79
G97 G04
G97 G09
G97 G72 X10 E40
G97 G73 r5 E40
G97 G74 X10 E40
G97 G93
G97 G94
G97 G95
G97 G35
