; Table 2.4 (G congruence in one block), row G91: `ncc check` pairs G91 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1982): G91 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 1 1 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G91: h. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G91 itself (6):
G91 G17
G91 G18
G91 G19
G91 G90
G91 G91
G91 G79
; Compatible: no cell says 1 and not one class, no error (36):
G91 G00
G91 G01
G91 G06
G91 G02
G91 G03
G91 G33
G91 G34
G91 G27
G91 G28
G91 G29
G91 G21
G91 G20
G91 G40
G91 G41
G91 G42
G91 G70
G91 G71
G91 G80
G91 G81
G91 G82
G91 G83
G91 G84
G91 G85
G91 G86
G91 G89
G91 G04
G91 G09
G91 G72 X10 E40
G91 G73 r5 E40
G91 G74 X10 E40
G91 G93
G91 G94
G91 G95
G91 G96
G91 G97
G91 G35
