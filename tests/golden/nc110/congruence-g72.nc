; Table 2.4 (G congruence in one block), row G72: `ncc check` pairs G72 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1969): G72 0 1 1 1 1 1 1 1 1 1 1 1 1 0 0 0 1 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G72: k. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G72 itself (27):
G72 G01 X10 E40
G72 G02 X10 E40
G72 G03 X10 E40
G72 G33 X10 E40
G72 G17 X10 E40
G72 G18 X10 E40
G72 G19 X10 E40
G72 G27 X10 E40
G72 G28 X10 E40
G72 G29 X10 E40
G72 G21 X10 E40
G72 G20 X10 E40
G72 G40 X10 E40
G72 G41 X10 E40
G72 G42 X10 E40
G72 G80 X10 E40
G72 G81 X10 E40
G72 G82 X10 E40
G72 G83 X10 E40
G72 G84 X10 E40
G72 G85 X10 E40
G72 G86 X10 E40
G72 G89 X10 E40
G72 G79 X10 E40
G72 G72 X10 E40
G72 G73 r5 E40
G72 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (5):
G72 G06 X10 E40
G72 G34 X10 E40
G72 G04 X10 E40
G72 G09 X10 E40
G72 G35 X10 E40
; Compatible: no cell says 1 and not one class, no error (10):
G72 G00 X10 E40
G72 G70 X10 E40
G72 G71 X10 E40
G72 G90 X10 E40
G72 G91 X10 E40
G72 G93 X10 E40
G72 G94 X10 E40
G72 G95 X10 E40
G72 G96 X10 E40
G72 G97 X10 E40
