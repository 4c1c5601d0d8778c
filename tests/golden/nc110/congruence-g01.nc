; Table 2.4 (G congruence in one block), row G01: `ncc check` pairs G01 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1947): G01 1 1 1 1 0 1 0 1 1 0 0 0 0 0 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G01: a. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G01 itself (11):
G01 G00
G01 G01
G01 G02
G01 G03
G01 G33
G01 G17
G01 G18
G01 G19
G01 G21
G01 G20
G01 G80
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (5):
G01 G06
G01 G34
G01 G72 X10 E40
G01 G73 r5 E40
G01 G74 X10 E40
; Compatible: no cell says 1 and not one class, no error (26):
G01 G27
G01 G28
G01 G29
G01 G40
G01 G41
G01 G42
G01 G70
G01 G71
G01 G81
G01 G82
G01 G83
G01 G84
G01 G85
G01 G86
G01 G89
G01 G90
G01 G91
G01 G79
G01 G04
G01 G09
G01 G93
G01 G94
G01 G95
G01 G96
G01 G97
G01 G35
