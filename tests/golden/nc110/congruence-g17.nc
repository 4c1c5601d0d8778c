; Table 2.4 (G congruence in one block), row G17: `ncc check` pairs G17 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1953): G17 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G17: b. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G17 itself (34):
G17 G00
G17 G01
G17 G02
G17 G03
G17 G33
G17 G17
G17 G18
G17 G19
G17 G27
G17 G28
G17 G29
G17 G21
G17 G20
G17 G40
G17 G41
G17 G42
G17 G70
G17 G71
G17 G80
G17 G81
G17 G82
G17 G83
G17 G84
G17 G85
G17 G86
G17 G89
G17 G90
G17 G91
G17 G79
G17 G04
G17 G09
G17 G72 X10 E40
G17 G73 r5 E40
G17 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (6):
G17 G06
G17 G34
G17 G93
G17 G94
G17 G97
G17 G35
; Incompatible only by the class rule / ncc's rows for G95 G96 (no printed cell says 1) (2):
G17 G95
G17 G96
; Compatible: no cell says 1 and not one class, no error (0):
