; Table 2.4 (G congruence in one block), row G94: `ncc check` pairs G94 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1984): G94 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G94: l. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G94 itself (3):
G94 G17
G94 G18
G94 G19
; Incompatible only by the class rule / ncc's rows for G95 G96 (no printed cell says 1) (3):
G94 G93
G94 G94
G94 G95
; Compatible: no cell says 1 and not one class, no error (36):
G94 G00
G94 G01
G94 G06
G94 G02
G94 G03
G94 G33
G94 G34
G94 G27
G94 G28
G94 G29
G94 G21
G94 G20
G94 G40
G94 G41
G94 G42
G94 G70
G94 G71
G94 G80
G94 G81
G94 G82
G94 G83
G94 G84
G94 G85
G94 G86
G94 G89
G94 G90
G94 G91
G94 G79
G94 G04
G94 G09
G94 G72 X10 E40
G94 G73 r5 E40
G94 G74 X10 E40
G94 G96
G94 G97
G94 G35
