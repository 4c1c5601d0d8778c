; G27/G28/G29, G09 and G04 (§2.8.5 L2969-3095, §2.8.11; decision 44): the modes are path
; events (shown when the mode changes); G09 is a path decelerate event in its block; a
; G27/G28 profile starts at a feed move and runs until a G00 move, a G09 or G04 block, or
; G29; M, S and T may stand only outside it. Every block here is legal.
; N1 path continuous (G28); N3 path decelerate, the profile ends with N3; N4 S is legal;
; N5 starts a profile again, N6 ends it (G04 after the move, TMR 0: dwell 0); N7 T legal;
; N9 a rapid ends the profile; N10 M03 legal; N11 path corner_slowdown (G27); N12 path
; point_to_point (G29) ends it; N13 M05 legal; N14 G27 again; N16 G28 changes the mode
; but the profile of N15 runs on; N17 a rapid ends it; N18 M09 legal.
N1 G28 G1 X10 F100
N2 X20
N3 G09 X30
N4 S200
N5 X40
N6 G4 X50
N7 T1
N8 X60
N9 G0 X70
N10 M3
N11 G27 G1 X80
N12 G29
N13 M5
N14 G27
N15 G1 X90
N16 G28
N17 G0 X0
N18 M9
