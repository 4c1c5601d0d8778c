; M, S and T inside a running G27/G28 profile (§2.8.5 L3056-3063: "during a continuous
; profile (G27-G28) the auxiliary functions M, S and T are not allowed"; decision 44),
; ncc check: NC4053 "<words> cannot stand inside a running G27 profile: end it first
; with a G00 move, or G09 or G04", at the block (column 1).
; Expected: N2 "M08 ... G27" (9:1); N3 "S100 ..." (10:1); N4 "T1 ..." (11:1); N5 "M03,
; S200 and T1 ..." (12:1); N7 under G28 (the profile of N6 runs on): "M09 ... G28" (14:1). N9 after
; the G09 block N8: no error.
N1 G1 X10 F100
N2 M8
N3 S100
N4 T1
N5 X20 S200 M3 T1
N6 G28 X30
N7 M9
N8 G9 X40
N9 M9
