; Helix limits (§2.8.1.6; decision 41), ncc check. G29: no G27 profile rule.
; Expected:
;  N2 K0.0001 over 1000 mm: 10000000 turns: NC4044 "the helix would make 10000000 turns;
;     at most 1000000" (9:27).
;  N4 K without travel along Z (not a helix): NC4025 warning "K has no effect in this
;     block" (11:23).
N0 G29 G0 X10 Y0 Z0
N1 G1 X10 F100
N2 G3 X10 Y0 Z-1000 I0 J0 K0.0001
N3 G0 X10 Y0 Z0
N4 G3 X0 Y10 Z0 I0 J0 K2
