; Table 2.4 (G congruence in one block), row G02: `ncc check` pairs G02 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1948): G02 1 1 1 1 1 1 1 1 1 0 0 0 0 0 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G02: a. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G02 itself (21):
G02 G00
G02 G01
G02 G02
G02 G03
G02 G33
G02 G17
G02 G18
G02 G19
G02 G21
G02 G20
G02 G80
G02 G81
G02 G82
G02 G83
G02 G84
G02 G85
G02 G86
G02 G89
G02 G72 X10 E40
G02 G73 r5 E40
G02 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (2):
G02 G06
G02 G34
; Compatible: no cell says 1 and not one class, no error (19):
G02 G27
G02 G28
G02 G29
G02 G40
G02 G41
G02 G42
G02 G70
G02 G71
G02 G90
G02 G91
G02 G79
G02 G04
G02 G09
G02 G93
G02 G94
G02 G95
G02 G96
G02 G97
G02 G35
