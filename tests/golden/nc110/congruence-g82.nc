; Table 2.4 (G congruence in one block), row G82: `ncc check` pairs G82 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1975): G82 0 0 1 1 1 1 1 1 1 1 1 1 1 0 0 0 1 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G82: g. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G82 itself (26):
G82 G02
G82 G03
G82 G33
G82 G17
G82 G18
G82 G19
G82 G27
G82 G28
G82 G29
G82 G21
G82 G20
G82 G40
G82 G41
G82 G42
G82 G80
G82 G81
G82 G82
G82 G83
G82 G84
G82 G85
G82 G86
G82 G89
G82 G79
G82 G72 X10 E40
G82 G73 r5 E40
G82 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (5):
G82 G06
G82 G34
G82 G04
G82 G09
G82 G35
; Compatible: no cell says 1 and not one class, no error (11):
G82 G00
G82 G01
G82 G70
G82 G71
G82 G90
G82 G91
G82 G93
G82 G94
G82 G95
G82 G96
G82 G97
