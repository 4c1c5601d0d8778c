; Table 2.4 (G congruence in one block), row G29: `ncc check` pairs G29 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1960): G29 0 0 0 0 1 0 1 0 0 0 0 1 1 0 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G29: c. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G29 itself (16):
G29 G17
G29 G18
G29 G19
G29 G27
G29 G28
G29 G29
G29 G81
G29 G82
G29 G83
G29 G84
G29 G85
G29 G86
G29 G89
G29 G72 X10 E40
G29 G73 r5 E40
G29 G74 X10 E40
; Compatible: no cell says 1 and not one class, no error (26):
G29 G00
G29 G01
G29 G06
G29 G02
G29 G03
G29 G33
G29 G34
G29 G21
G29 G20
G29 G40
G29 G41
G29 G42
G29 G70
G29 G71
G29 G80
G29 G90
G29 G91
G29 G79
G29 G04
G29 G09
G29 G93
G29 G94
G29 G95
G29 G96
G29 G97
G29 G35
