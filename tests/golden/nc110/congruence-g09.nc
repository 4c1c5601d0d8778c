; Table 2.4 (G congruence in one block), row G09: `ncc check` pairs G09 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1952): G09 0 0 0 1 1 0 1 0 0 0 0 1 0 1 1 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G09: j. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G09 itself (18):
G09 G33
G09 G17
G09 G18
G09 G19
G09 G27
G09 G28
G09 G81
G09 G82
G09 G83
G09 G84
G09 G85
G09 G86
G09 G89
G09 G04
G09 G09
G09 G72 X10 E40
G09 G73 r5 E40
G09 G74 X10 E40
; Compatible: no cell says 1 and not one class, no error (24):
G09 G00
G09 G01
G09 G06
G09 G02
G09 G03
G09 G34
G09 G29
G09 G21
G09 G20
G09 G40
G09 G41
G09 G42
G09 G70
G09 G71
G09 G80
G09 G90
G09 G91
G09 G79
G09 G93
G09 G94
G09 G95
G09 G96
G09 G97
G09 G35
