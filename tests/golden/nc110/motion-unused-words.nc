; Words a motion does not use are reported (NC4025 warning "<word> has no effect in this
; block", at the word), ncc check. G29: no G27 profile rule.
; Expected: N1 R on a line (6:20); N2 I and J on a rapid (7:11, 7:14); N3 K on a line
; (8:11). N4 F on a rapid is stored for later feed moves (§2.8.1.1 L2050): no warning, and
; N5 runs at it (no NC4001).
N1 G29 G1 X10 F100 R5
N2 G0 X20 I5 J5
N3 G1 X30 K2
N4 G0 X40 F200
N5 G1 X50
