; corpus-2.13.2.2-cls-example-2: copy of corpus part4/2.13.2.2-CLS-example-2-
; main.nc (§2.13.2.2, seed L8445-8450), the main program of the call layout;
; P800 is lib/MP0/P800.nc (no device: MP0, decision 21).
; Expected (derived): N17 and N67 each run P800 once, and the run goes on at
; N18 and N68: N16, P800 (E30=1, X1), N18, N67, P800 (E30=2, X2), N68.
; Changed: the manual elides the blocks N16, N18, N68 ("...........") and the
; blocks between N18 and N67 (a line of dots, kept as a comment); messages are
; supplied for N16, N18, N68; N69 G X0 M30 is added (the fragment has no end).
N16 (DIS,"N16")
N17 (CLS,P800)
N18 (DIS,"N18")
;...............
N67 (CLS,P800)
N68 (DIS,"N68")
N69 G X0 M30
