; Table 2.4 (G congruence in one block), row G93: `ncc check` pairs G93 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1983): G93 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G93: l. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G93 itself (3):
G93 G17
G93 G18
G93 G19
; Incompatible only by the class rule / ncc's rows for G95 G96 (no printed cell says 1) (3):
G93 G93
G93 G94
G93 G95
; Compatible: no cell says 1 and not one class, no error (36):
G93 G00
G93 G01
G93 G06
G93 G02
G93 G03
G93 G33
G93 G34
G93 G27
G93 G28
G93 G29
G93 G21
G93 G20
G93 G40
G93 G41
G93 G42
G93 G70
G93 G71
G93 G80
G93 G81
G93 G82
G93 G83
G93 G84
G93 G85
G93 G86
G93 G89
G93 G90
G93 G91
G93 G79
G93 G04
G93 G09
G93 G72 X10 E40
G93 G73 r5 E40
G93 G74 X10 E40
G93 G96
G93 G97
G93 G35
