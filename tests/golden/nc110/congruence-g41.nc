; Table 2.4 (G congruence in one block), row G41: `ncc check` pairs G41 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1965): G41 0 0 0 1 1 1 1 0 1 1 1 0 0 0 0 0 1 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G41: e. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G41 itself (20):
G41 G33
G41 G17
G41 G18
G41 G19
G41 G20
G41 G40
G41 G41
G41 G42
G41 G80
G41 G81
G41 G82
G41 G83
G41 G84
G41 G85
G41 G86
G41 G89
G41 G79
G41 G72 X10 E40
G41 G73 r5 E40
G41 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (2):
G41 G06
G41 G34
; Compatible: no cell says 1 and not one class, no error (20):
G41 G00
G41 G01
G41 G02
G41 G03
G41 G27
G41 G28
G41 G29
G41 G21
G41 G70
G41 G71
G41 G90
G41 G91
G41 G04
G41 G09
G41 G93
G41 G94
G41 G95
G41 G96
G41 G97
G41 G35
