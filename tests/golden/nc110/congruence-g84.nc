; Table 2.4 (G congruence in one block), row G84: `ncc check` pairs G84 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1977): G84 0 0 1 1 1 1 1 1 1 1 1 1 1 0 0 0 1 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G84: g. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G84 itself (26):
G84 G02
G84 G03
G84 G33
G84 G17
G84 G18
G84 G19
G84 G27
G84 G28
G84 G29
G84 G21
G84 G20
G84 G40
G84 G41
G84 G42
G84 G80
G84 G81
G84 G82
G84 G83
G84 G84
G84 G85
G84 G86
G84 G89
G84 G79
G84 G72 X10 E40
G84 G73 r5 E40
G84 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (5):
G84 G06
G84 G34
G84 G04
G84 G09
G84 G35
; Compatible: no cell says 1 and not one class, no error (11):
G84 G00
G84 G01
G84 G70
G84 G71
G84 G90
G84 G91
G84 G93
G84 G94
G84 G95
G84 G96
G84 G97
