; Corpus copy of part2/2.8.1.7-G33-multistart-example.nc (seed §2.8.1.7, L2776-2786): a
; three-start thread from one start point, the passes at spindle angles 0, 120 and 240
; degrees (R, decision 42).
; Changed: the manual's annotations ("первый заход" first pass, "второй заход", "третий
; заход") are dropped; its dotted elisions are replaced by a return to the start point
; (N38, N42: G0 Z33, G0 X20 Z33 is the supplied start), and the spindle (S100, M03) and
; the start (N1, N2) are supplied.
; Expected: three threads to Z3 of pitch 6, phase 0 (not shown), 120, 240; each 30 mm
; = 5 turns at 100 rpm = 3 s.
N1 S100 M3
N2 G0 X20 Z33
N37 G33 Z3 K6
N38 G0 Z33
N41 G33 Z3 K6 R120
N42 G0 Z33
N45 G33 Z3 K6 R240
N46 G0 Z33
