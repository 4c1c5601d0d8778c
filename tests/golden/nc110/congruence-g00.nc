; Table 2.4 (G congruence in one block), row G00: `ncc check` pairs G00 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1946): G00 1 1 1 1 0 1 0 1 1 0 0 0 0 0 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G00: a. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G00 itself (11):
G00 G00
G00 G01
G00 G02
G00 G03
G00 G33
G00 G17
G00 G18
G00 G19
G00 G21
G00 G20
G00 G80
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (3):
G00 G06
G00 G34
G00 G35
; Compatible: no cell says 1 and not one class, no error (28):
G00 G27
G00 G28
G00 G29
G00 G40
G00 G41
G00 G42
G00 G70
G00 G71
G00 G81
G00 G82
G00 G83
G00 G84
G00 G85
G00 G86
G00 G89
G00 G90
G00 G91
G00 G79
G00 G04
G00 G09
G00 G72 X10 E40
G00 G73 r5 E40
G00 G74 X10 E40
G00 G93
G00 G94
G00 G95
G00 G96
G00 G97
