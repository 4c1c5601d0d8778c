; corpus-2.13.3.1-rpt-example-1: copy of corpus part4/2.13.3.1-RPT-example-1.nc
; (§2.13.3.1, figure 2.120, seed L8630-8651): three equal slots, nested RPT and
; a cumulative UIO (decision 26).
; Expected (derived): the outer body N3-N16 runs 3 times, the inner body N6-N13
; twice a pass: 6 contours. Per slot Z2, then Z-6 and Z-14 (N6 is G91 Z-8; the
; first N6 of a slot moves in G00, still modal from N1/N15; the second in G01
; from N7). Contour from the slot origin: X40Y20 -> X60 -> Y50 -> X20 -> Y20 ->
; X40 -> Y35. Slot origins (0,0), (80,20), (160,40); after the loop (240,60)
; until N18 (UAO,0); N19 Z20; N20 to X0 Y0 of origin 0 and M30.
; Not supported yet: cutter compensation. Removed: G41 from N7 and G40 from N12
; (the trace is the programmed path).
; Changed: 'N20 XYM 30' (both renderings) is spelled 'N20 X Y M30'; both read X, Y, M30.
; Tools: profiles/flow-tools.toml (T6.6).
(DIS," N 3 паза")
(DIS,".........")
N1  S600 T6.6 M6 M3
N2  (RPT,3)
N3  X40 Y35
N4  Z2
N5  (RPT,2)
N6  G91 Z-8
N7  G90 G1 X40 Y20 F300
N8  X60
N9  Y50
N10 X20
N11 Y20
N12 X40
N13 Y35 F1000
N14 (ERP)
N15 G Z2
N16 (UIO,X80,Y20)
N17 (ERP)
N18 (UAO,0)
N19 Z20
N20 X Y M30
