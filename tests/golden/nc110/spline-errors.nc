; The structure of a spline (§2.8.1.3, L2127-2224; decision 43) and its errors, all
; NC4052, ncc check (the dry run goes on after each). G29: no G27 profile rule.
; Expected:
;  N1 G06 outside BSP...ESP: "G06 stands only between (BSP) and (ESP)" (23:1).
;  N4 G06 straight after BSP: "G06 needs the lead-in first: a G00 or G01 block after
;     (BSP) goes to the spline's start" (26:1).
;  N5 ESP after the failed G06: nothing more is reported.
;  N9 a G01 block where the first G06 point belongs: "the block after the lead-in is G06
;     with the spline's first point" (31:1); N10 ESP: no lead-out (32:6).
;  N14 a point equal to the one before: "a spline point equal to the one before it"
;     (36:1).
;  N15 G02 inside the spline: "G02 cannot stand inside a spline: only G06 points and the
;     G00 or G01 lead-out" (37:5, at G2) (the manual's message 4 77 «Неконгруэнтный
;     профиль»).
;  N20 BSP axes not those of the plane XY: "the spline's axes XZ must be those of the
;     plane XY" (40:6).
;  N22 ESP without BSP (the failed BSP opened nothing): "(ESP) without (BSP)" (42:6).
;  N24 BSP inside an open spline: "a spline is already open: end it with (ESP)" (44:6).
;  N28 G06 after the lead-out: "G06 after the spline's lead-out: (ESP) comes first" (48:1).
;  N33 the program ends inside a spline: "the program ended inside a spline: (ESP) is
;     missing", at the last block (53:1).
N0 G29 G1 X0 Y0 F100
N1 G06 X10 Y10
N2 G1 X0 Y0
N3 (BSP,X,Y,0)
N4 G06 X10 Y10
N5 (ESP)
N6 G0 X0 Y0
N7 (BSP,X,Y,0)
N8 G1 X5 Y0
N9 G1 X10 Y0
N10 (ESP)
N11 (BSP,X,Y,0)
N12 G1 X0 Y0
N13 G06 X10 Y0
N14 X10 Y0
N15 G2 X20 Y0 I15 J0
N16 G1 X30 Y0
N17 (ESP)
N20 (BSP,X,Z,0)
N21 G1 X40 Y0
N22 (ESP)
N23 (BSP,X,Y,0)
N24 (BSP,X,Y,0)
N25 G1 X50 Y10
N26 G6 X60 Y0
N27 G1 X70 Y0
N28 G6 X80 Y0
N29 (ESP)
N30 (BSP,X,Y,0)
N31 G1 X0 Y0
N32 G6 X10 Y10
N33 G1 X20 Y0
