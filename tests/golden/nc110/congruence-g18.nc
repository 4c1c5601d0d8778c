; Table 2.4 (G congruence in one block), row G18: `ncc check` pairs G18 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1954): G18 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G18: b. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G18 itself (34):
G18 G00
G18 G01
G18 G02
G18 G03
G18 G33
G18 G17
G18 G18
G18 G19
G18 G27
G18 G28
G18 G29
G18 G21
G18 G20
G18 G40
G18 G41
G18 G42
G18 G70
G18 G71
G18 G80
G18 G81
G18 G82
G18 G83
G18 G84
G18 G85
G18 G86
G18 G89
G18 G90
G18 G91
G18 G79
G18 G04
G18 G09
G18 G72 X10 E40
G18 G73 r5 E40
G18 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (6):
G18 G06
G18 G34
G18 G93
G18 G94
G18 G97
G18 G35
; Incompatible only by the class rule / ncc's rows for G95 G96 (no printed cell says 1) (2):
G18 G95
G18 G96
; Compatible: no cell says 1 and not one class, no error (0):
