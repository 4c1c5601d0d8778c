; Table 2.4 (G congruence in one block), row G34: `ncc check` pairs G34 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1962): G34 1 1 1 1 1 1 1 1 1 1 1 0 0 0 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G34: a. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G34 itself (24):
G34 G00
G34 G01
G34 G02
G34 G03
G34 G33
G34 G17
G34 G18
G34 G19
G34 G21
G34 G20
G34 G40
G34 G41
G34 G42
G34 G80
G34 G81
G34 G82
G34 G83
G34 G84
G34 G85
G34 G86
G34 G89
G34 G72 X10 E40
G34 G73 r5 E40
G34 G74 X10 E40
; Incompatible only by the class rule / ncc's rows for G95 G96 (no printed cell says 1) (2):
G34 G06
G34 G34
; Compatible: no cell says 1 and not one class, no error (16):
G34 G27
G34 G28
G34 G29
G34 G70
G34 G71
G34 G90
G34 G91
G34 G79
G34 G04
G34 G09
G34 G93
G34 G94
G34 G95
G34 G96
G34 G97
G34 G35
