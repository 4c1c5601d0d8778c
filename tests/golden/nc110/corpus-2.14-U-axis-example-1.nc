; Copy of corpus part4/2.14-U-axis-example-1.nc (NC-110 §2.14, Fig. 2.135, seed lines
; 9968-9990): a boring and facing head with a diametral U axis finishes two holes. The
; annotations after the blocks are dropped. Corrected: N117 is printed "F60,S630" (both
; renderings); here F60 S630 (the printed form is corpus-2.14-U-axis-example-1-as-printed).
; Profile frame-uaxis: U diametral, origin 1 the head's, tools T9.9 and T10.
; Checks: the corners r5 (N130) and r-3 (N132) are fillets of the compensated path
; (§2.8.7, decision 74). T10 has no corrector: radius 0, so the tool's centre runs on the
; profile with its corners cut, in the Z-U plane as programmed (U in diameters,
; decision 75). By hand: N129 (to Z-15) ends 5 before its corner, at Z-10; the r5 arc
; about (Z-10, U94.975) turns counter-clockwise 90 deg to (Z-15, U94.975); N131 (to U60)
; ends where the r-3 arc, tangent to it and to N133 (to Z-40 U40, at -141.340 deg),
; begins: its centre (Z-18, U60 + 3 tan(51.340 / 2) = 61.442); the arc turns clockwise
; 51.340 deg. (DPI,Z,U) under the power-on G27 has no error (decision 32). The run of
; the program without those two blocks is corpus-2.14-U-axis-example-1-no-corners.
N116 (DIS,".....................")
N117 F60 S630 T9.9 M6
N118 (DPI,Z,U)
N119 (UAO,1)
N120 (UOT,0,Z-200)
N121 X Y160 T10 M3
N122 G41 Z2 U51
N123 G1 Z-1 U44.98
N124 Z-44
N125 G G40 U40
N126 Z2 F40 S380
N127 G41 Y U106
N128 G1 Z-1 U99.975
N129 Z-15
N130 r5
N131 U60
N132 r-3
N133 Z-40 U40
N134 G40 Z-44
N135 G U35
N136 Z100 M5
N137 (DPI,X,Y)
N138 (UAO,0)
