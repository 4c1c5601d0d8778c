; Table 2.4 (G congruence in one block), row G03: `ncc check` pairs G03 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1949): G03 1 1 1 1 1 1 1 1 1 0 0 0 0 0 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G03: a. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G03 itself (21):
G03 G00
G03 G01
G03 G02
G03 G03
G03 G33
G03 G17
G03 G18
G03 G19
G03 G21
G03 G20
G03 G80
G03 G81
G03 G82
G03 G83
G03 G84
G03 G85
G03 G86
G03 G89
G03 G72 X10 E40
G03 G73 r5 E40
G03 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (2):
G03 G06
G03 G34
; Compatible: no cell says 1 and not one class, no error (19):
G03 G27
G03 G28
G03 G29
G03 G40
G03 G41
G03 G42
G03 G70
G03 G71
G03 G90
G03 G91
G03 G79
G03 G04
G03 G09
G03 G93
G03 G94
G03 G95
G03 G96
G03 G97
G03 G35
