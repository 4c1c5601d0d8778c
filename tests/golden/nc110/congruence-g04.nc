; Table 2.4 (G congruence in one block), row G04: `ncc check` pairs G04 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1950): G04 0 0 0 1 1 0 1 0 0 0 0 1 0 1 1 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G04: j. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G04 itself (18):
G04 G33
G04 G17
G04 G18
G04 G19
G04 G27
G04 G28
G04 G81
G04 G82
G04 G83
G04 G84
G04 G85
G04 G86
G04 G89
G04 G04
G04 G09
G04 G72 X10 E40
G04 G73 r5 E40
G04 G74 X10 E40
; Compatible: no cell says 1 and not one class, no error (24):
G04 G00
G04 G01
G04 G06
G04 G02
G04 G03
G04 G34
G04 G29
G04 G21
G04 G20
G04 G40
G04 G41
G04 G42
G04 G70
G04 G71
G04 G80
G04 G90
G04 G91
G04 G79
G04 G93
G04 G94
G04 G95
G04 G96
G04 G97
G04 G35
