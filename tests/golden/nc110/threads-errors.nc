; Thread errors (§2.8.1.7 L2584-2598; decision 42), ncc check. G29: no G27 profile rule.
; Expected:
;  N2 no K (K is needed in every block): NC4010 "thread block needs exactly one pitch word
;     K; none is programmed" (11:1).
;  N4 K0: NC4042 "thread pitch K0 must be greater than zero" (13:13).
;  N6 K-1: NC4042 "thread pitch K-1 must be greater than zero" (15:13).
;  N8 the spindle stopped (M05 in N7): NC4013 "thread cutting needs a turning spindle
;     (M03/M04 with S > 0)" (17:1).
N0 G29 S100 M3
N1 G0 Z0
N2 G33 Z-50
N3 G0 Z0
N4 G33 Z-50 K0
N5 G0 Z0
N6 G33 Z-50 K-1
N7 G0 Z0 M5
N8 G33 Z-50 K2
