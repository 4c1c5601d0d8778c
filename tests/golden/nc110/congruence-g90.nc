; Table 2.4 (G congruence in one block), row G90: `ncc check` pairs G90 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1981): G90 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1 1 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G90: h. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G90 itself (6):
G90 G17
G90 G18
G90 G19
G90 G90
G90 G91
G90 G79
; Compatible: no cell says 1 and not one class, no error (36):
G90 G00
G90 G01
G90 G06
G90 G02
G90 G03
G90 G33
G90 G34
G90 G27
G90 G28
G90 G29
G90 G21
G90 G20
G90 G40
G90 G41
G90 G42
G90 G70
G90 G71
G90 G80
G90 G81
G90 G82
G90 G83
G90 G84
G90 G85
G90 G86
G90 G89
G90 G04
G90 G09
G90 G72 X10 E40
G90 G73 r5 E40
G90 G74 X10 E40
G90 G93
G90 G94
G90 G95
G90 G96
G90 G97
G90 G35
