; corpus-2.13.3.2-epp-example-1: copy of corpus part4/2.13.3.2-EPP-example-1.nc
; (§2.13.3.2, figure 2.123, seed L8769-8794): one profile for the roughing and
; the finishing pass.
; Expected (derived): N8-N21 run twice: in sequence with T4.4 F400 S2000 UOV=1,
; then through N25 (EPP,START,END) with T5.5 F500 S2500 UOV=0; then N26.
; Not supported yet: GTL and cutter compensation. Removed: the GTL definitions
; N1-N4 (l1=X-35 Y25,a10; l2=X-35 Y25,a100; l3=X Y-25,a180; c1, OCR '180 JO
; r60' for I80 J0 r60), G21 G42 (N11) and G20 G40 (N18), and the corner rounds
; r-12 (N13, N15, left empty). Supplied instead (the trace is a G01/G02 path,
; not the figure's exact profile): N11 onto the corner l2/l1 (-35,25); N12
; along l1 to where it leaves c1, (111.794,50.884); N14 G02 along c1 about
; (80,0) to where it meets l3, (134.544,-25); N16 along l3 to l3/l2,
; (-26.184,-25); N17 along l2 back to (-35,25); N18 G01 back to the start
; point X-20 Y15. UOV, the allowance, has no effect without compensation.
; Added: N26, the elided rest, reads G Z50 M30.
; Tools: profiles/flow-tools.toml (T4.4, T5.5).
N5  (DIS,"ЧЕРНОВОЙ ПРОХОД ФРЕЗА D=8")
N6  F400 S2000 T4.4 M6 M3
N7  UOV=1
"START" N8
N9  G X-20 Y15
N10 Z-10
N11 G1 X-35 Y25
N12 X111.794 Y50.884
N13
N14 G2 X134.544 Y-25 I80 J0
N15
N16 G1 X-26.184 Y-25
N17 X-35 Y25
N18 X-20 Y15
N19 G X-20 Y15
N20 Z
"END" N21
N22 (DIS,"ФИНИШНЫЙ ПРОХОД ФРЕЗА D=8")
N23 F500 S2500 T5.5 M6 M3
N24 UOV=0
N25 (EPP,START,END)
N26 G Z50 M30
