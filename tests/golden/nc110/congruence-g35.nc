; Table 2.4 (G congruence in one block), row G35: `ncc check` pairs G35 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1963): G35 1 0 0 1 1 1 1 0 1 0 0 0 0 0 0 0 0 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G35: n (Table 2.2 only; Table 2.5 has no G35). Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G35 itself (17):
G35 G00
G35 G33
G35 G17
G35 G18
G35 G19
G35 G20
G35 G80
G35 G81
G35 G82
G35 G83
G35 G84
G35 G85
G35 G86
G35 G89
G35 G72 X10 E40
G35 G73 r5 E40
G35 G74 X10 E40
; Incompatible only by the class rule / ncc's rows for G95 G96 (no printed cell says 1) (1):
G35 G35
; Compatible: no cell says 1 and not one class, no error (24):
G35 G01
G35 G06
G35 G02
G35 G03
G35 G34
G35 G27
G35 G28
G35 G29
G35 G21
G35 G40
G35 G41
G35 G42
G35 G70
G35 G71
G35 G90
G35 G91
G35 G79
G35 G04
G35 G09
G35 G93
G35 G94
G35 G95
G35 G96
G35 G97
