; Table 2.4 (G congruence in one block), row G19: `ncc check` pairs G19 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1955): G19 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G19: b. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G19 itself (34):
G19 G00
G19 G01
G19 G02
G19 G03
G19 G33
G19 G17
G19 G18
G19 G19
G19 G27
G19 G28
G19 G29
G19 G21
G19 G20
G19 G40
G19 G41
G19 G42
G19 G70
G19 G71
G19 G80
G19 G81
G19 G82
G19 G83
G19 G84
G19 G85
G19 G86
G19 G89
G19 G90
G19 G91
G19 G79
G19 G04
G19 G09
G19 G72 X10 E40
G19 G73 r5 E40
G19 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (6):
G19 G06
G19 G34
G19 G93
G19 G94
G19 G97
G19 G35
; Incompatible only by the class rule / ncc's rows for G95 G96 (no printed cell says 1) (2):
G19 G95
G19 G96
; Compatible: no cell says 1 and not one class, no error (0):
