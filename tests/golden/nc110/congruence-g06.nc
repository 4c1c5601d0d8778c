; Table 2.4 (G congruence in one block), row G06: `ncc check` pairs G06 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1951): G06 1 1 1 1 1 1 1 1 1 1 1 0 0 0 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G06: a. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G06 itself (24):
G06 G00
G06 G01
G06 G02
G06 G03
G06 G33
G06 G17
G06 G18
G06 G19
G06 G21
G06 G20
G06 G40
G06 G41
G06 G42
G06 G80
G06 G81
G06 G82
G06 G83
G06 G84
G06 G85
G06 G86
G06 G89
G06 G72 X10 E40
G06 G73 r5 E40
G06 G74 X10 E40
; Incompatible only by the class rule / ncc's rows for G95 G96 (no printed cell says 1) (2):
G06 G06
G06 G34
; Compatible: no cell says 1 and not one class, no error (16):
G06 G27
G06 G28
G06 G29
G06 G70
G06 G71
G06 G90
G06 G91
G06 G79
G06 G04
G06 G09
G06 G93
G06 G94
G06 G95
G06 G96
G06 G97
G06 G35
