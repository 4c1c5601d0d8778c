; Table 2.4 (G congruence in one block), row G27: `ncc check` pairs G27 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1958): G27 0 0 0 0 1 0 1 0 0 0 0 1 1 1 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G27: c. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G27 itself (17):
G27 G17
G27 G18
G27 G19
G27 G27
G27 G28
G27 G29
G27 G81
G27 G82
G27 G83
G27 G84
G27 G85
G27 G86
G27 G89
G27 G04
G27 G72 X10 E40
G27 G73 r5 E40
G27 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (1):
G27 G09
; Compatible: no cell says 1 and not one class, no error (24):
G27 G00
G27 G01
G27 G06
G27 G02
G27 G03
G27 G33
G27 G34
G27 G21
G27 G20
G27 G40
G27 G41
G27 G42
G27 G70
G27 G71
G27 G80
G27 G90
G27 G91
G27 G79
G27 G93
G27 G94
G27 G95
G27 G96
G27 G97
G27 G35
