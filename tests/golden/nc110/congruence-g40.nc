; Table 2.4 (G congruence in one block), row G40: `ncc check` pairs G40 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1964): G40 0 0 0 1 1 1 1 0 0 1 1 0 0 0 0 0 1 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G40: e. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G40 itself (19):
G40 G33
G40 G17
G40 G18
G40 G19
G40 G40
G40 G41
G40 G42
G40 G80
G40 G81
G40 G82
G40 G83
G40 G84
G40 G85
G40 G86
G40 G89
G40 G79
G40 G72 X10 E40
G40 G73 r5 E40
G40 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (2):
G40 G06
G40 G34
; Compatible: no cell says 1 and not one class, no error (21):
G40 G00
G40 G01
G40 G02
G40 G03
G40 G27
G40 G28
G40 G29
G40 G21
G40 G20
G40 G70
G40 G71
G40 G90
G40 G91
G40 G04
G40 G09
G40 G93
G40 G94
G40 G95
G40 G96
G40 G97
G40 G35
