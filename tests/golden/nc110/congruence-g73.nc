; Table 2.4 (G congruence in one block), row G73: `ncc check` pairs G73 with every decoded G code.
; Rule: NC-110 §2.8 (seed lines 1894-1904), Table 2.4 (lines 1917-1986, "1" = incompatible),
; Table 2.5 classes (lines 1988-2009), docs/dialects/nc110.md decision 1: two codes are incompatible
; if EITHER printed cell says 1, or they are of one class of Table 2.5; G95/G96 take the rows of
; G93/G94/G97. The error NC3013 stands at the second code (column 5), its note at the first.
; Printed row (seed line 1970): G73 0 1 1 1 1 1 1 1 1 1 1 1 1 0 0 0 1 0 1
; Columns: 00|01|02 03|33|81-86 89|80|72 73 74|21|20|41 42|40|27 28|29|04|09|90 91|79|70 71|17 18 19
; Class of G73: k. Measuring codes carry X10 E40 (G72, G74) or r5 E40 (G73), as the
; block's last measuring code needs (NC3033); they change nothing in the G check.
; The first block ends the run (M30), so the dry run of `ncc check` executes none of the
; blocks below and the report holds only the static checks; blocks after M30 are still read
; and checked (decision 25; the manual puts error handlers after M30, §2.15).
M30
; Incompatible by the 1s of row G73 itself (27):
G73 G01 r5 E40
G73 G02 r5 E40
G73 G03 r5 E40
G73 G33 r5 E40
G73 G17 r5 E40
G73 G18 r5 E40
G73 G19 r5 E40
G73 G27 r5 E40
G73 G28 r5 E40
G73 G29 r5 E40
G73 G21 r5 E40
G73 G20 r5 E40
G73 G40 r5 E40
G73 G41 r5 E40
G73 G42 r5 E40
G73 G80 r5 E40
G73 G81 r5 E40
G73 G82 r5 E40
G73 G83 r5 E40
G73 G84 r5 E40
G73 G85 r5 E40
G73 G86 r5 E40
G73 G89 r5 E40
G73 G79 r5 E40
G73 G72 X10 E40
G73 G73 r5 E40
G73 G74 X10 E40
; Incompatible only by the partner's own row (the table is asymmetric here; "either cell") (5):
G73 G06 r5 E40
G73 G34 r5 E40
G73 G04 r5 E40
G73 G09 r5 E40
G73 G35 r5 E40
; Compatible: no cell says 1 and not one class, no error (10):
G73 G00 r5 E40
G73 G70 r5 E40
G73 G71 r5 E40
G73 G90 r5 E40
G73 G91 r5 E40
G73 G93 r5 E40
G73 G94 r5 E40
G73 G95 r5 E40
G73 G96 r5 E40
G73 G97 r5 E40
