; corpus-2.13.3.1-rpt-example-3: copy of corpus part4/2.13.3.1-RPT-example-3.nc
; (§2.13.3.1, figure 2.122, seed L8699-8714): a roughing and a finishing pass.
; Expected (derived): the body N6-N11 runs 2 times, with the allowance UOV 0.5,
; then 0: X60Y60 -> G3 to X60Y-60 about (60,0), R60, through (0,0) -> X100 ->
; G3 to X100Y60 about (100,0), R60, through (160,0) -> X60; I and J are the
; absolute centre under G90 (decision 39). Then Z20 and X0 Y0 with M30.
; Not supported yet: cutter compensation. Removed: G41 from N6 (the trace is the
; programmed path; UOV, the allowance, has no effect without it).
; Corrected: the last line is printed twice, 'N14 X Y M30' and 'N14 X Y M M30'
; (both renderings); only 'N14 X Y M30' is kept.
; Added: a second N5, (DIS,UOV), in the body to show the allowance of each pass.
; Tools: profiles/flow-tools.toml (T6.6).
(DIS,".........")
N1  S350 T6.6 M6
N2  X60 Y M3
N3  Z-50
N4  UOV=0.5
N5  (RPT,2)
N5  (DIS,UOV)
N6  G1 X60 Y60 F500
N7  G3 Y-60 I60 J
N8  G1 X100
N9  G3 Y60 I100 J
N10 G1 X60
N11 UOV=0
N12 (ERP)
N13 GZ 20 M5
N14 X Y M30
