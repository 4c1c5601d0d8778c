; Table 2.4 (G congruence in one block), row G85: `ncc check` pairs G85 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1978): G85 0 0 1 1 1 1 1 1 1 1 1 1 1 0 0 0 1 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G85: g. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G85 itself (26):
G85 G02
G85 G03
G85 G33
G85 G17
G85 G18
G85 G19
G85 G27
G85 G28
G85 G29
G85 G21
G85 G20
G85 G40
G85 G41
G85 G42
G85 G80
G85 G81
G85 G82
G85 G83
G85 G84
G85 G85
G85 G86
G85 G89
G85 G79
G85 G72 X10 E40
G85 G73 r5 E40
G85 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (5):
G85 G06
G85 G34
G85 G04
G85 G09
G85 G35
; Compatible: no cell says 1 and not one class, no error (11):
G85 G00
G85 G01
G85 G70
G85 G71
G85 G90
G85 G91
G85 G93
G85 G94
G85 G95
G85 G96
G85 G97
