; NC-110 §2.13.8 (seed lines 9782-9846): "(RQU, 10, 1, ZE40; KE41) - modifies tool 10,
; corrector 1; the Z increment is in E40, the diameter's K in E41". The ';' is a
; misprint for ',' (the -as-printed case); written with ',' and # (the increments do not
; come from a measuring cycle). Profile tooling: corrector 1 has length 75, radius 5
; and keeps its wear (0.1 on the length). E40 = 0.02: length 75.02, wear 0.12;
; E41 = -0.06: radius 5 - 0.03 = 4.97, the diameter's wear -0.06 (its maximum 0.1
; counts either way).
E40=0.02
E41=-0.06
# (RQU, 10, 1, ZE40, KE41)
