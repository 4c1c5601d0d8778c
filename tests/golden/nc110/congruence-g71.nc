; Table 2.4 (G congruence in one block), row G71: `ncc check` pairs G71 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1968): G71 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G71: f. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G71 itself (5):
G71 G17
G71 G18
G71 G19
G71 G70
G71 G71
; Compatible: no cell says 1 and not one class, no error (37):
G71 G00
G71 G01
G71 G06
G71 G02
G71 G03
G71 G33
G71 G34
G71 G27
G71 G28
G71 G29
G71 G21
G71 G20
G71 G40
G71 G41
G71 G42
G71 G80
G71 G81
G71 G82
G71 G83
G71 G84
G71 G85
G71 G86
G71 G89
G71 G90
G71 G91
G71 G79
G71 G04
G71 G09
G71 G72 X10 E40
G71 G73 r5 E40
G71 G74 X10 E40
G71 G93
G71 G94
G71 G95
G71 G96
G71 G97
G71 G35
