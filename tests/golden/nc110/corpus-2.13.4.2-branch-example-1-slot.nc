; corpus-2.13.4.2-branch-example-1-slot: copy of corpus part4/2.13.4.2-branch-
; example-1-slot.nc (§2.13.4.2 example 1, figure 2.130, seed L9261-9282): a
; slot cut in several depths with a BGT loop and a last pass through EPP.
; Expected (derived): the contour N6-N14 (X0Y-10, Y-20, X-30, Y20, X30, Y-20,
; X0, Y-10) is cut at Z-3.5, -7, -10.5, -14, -17.5, -21 by the loop (N17 jumps
; back while E31 > E32 = -24; it falls through at E31 = -24.5), then once more
; at Z-25 by N19 (EPP,START,END) (decision 22). At the end E31 = -25.
; Not supported yet: cutter compensation. Removed: G42 (N8) and G40 (N13).
; Changed: the manual's lines of dots are comments; N22 (DIS,E31) and N23 M30
; are added. Tools: profiles/flow-tools.toml (T1.1).
N1  (DIS,".....................")
N2  F500 S2000 T1.1 M6 M3
N3  E31=-3.5
N4  E32=-24
"START" N5
N6  G X Y-10
N7  Z E31
N8  G1 X Y-20
N9  X-30
N10 Y20
N11 X30
N12 Y-20
N13 X
N14 Y-10
"END" N15
N16 E31=E31-3.5
N17 (BGT,E31,E32,START)
N18 E31=-25
N19 (EPP,START,END)
N20 G Z10
N21 X Y
;......................
N22 (DIS,E31)
N23 M30
