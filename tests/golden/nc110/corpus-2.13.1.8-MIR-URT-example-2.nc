; Copy of corpus part4/2.13.1.8-MIR-URT-example-2.nc (NC-110 §2.13.1.8, example 2,
; Fig. 2.115, seed lines 8229-8242). The elision line after N111 is dropped.
; Checks: N103 G81 only stores the cycle, R3 Z-25 (decision 51); N104-N107 drill 4
; holes at the programmed (25,25) (40,10) (55,10) (70,25) rotated +20 degrees
; (counter-clockwise, decision 28) about the temporary origin X30 Y22 of origin 0:
; the manual's holes (44.942,54.043) (64.168,45.078) (78.263,50.208) (87.228,69.434)
; in origin-0 coordinates, which the trace shows from the active origin X30 Y22:
; X14.9418 Y32.0428, X34.1675 Y23.0777, X48.2629 Y28.208, X57.228 Y47.4337; N106 X55
; keeps Y10 in program coordinates (decision 29). The first hole's XY move runs at the
; start height Z100 (profile frame-tools), then each hole: rapid Z3, feed Z-25, rapid
; Z3. N108 G80 cancels the cycle and moves Z20 in the modal G00, not rotated; N109
; restores origin 0, N110 the rotation 0; N111 changes the tool.
N100 S2000 F200 T3.3 M6
N101 (UOT,0,X30,Y22)
N102 (URT,20)
N103 G81 R3 Z-25 M3
N104 X25 Y25
N105 X40 Y10
N106 X55
N107 X70 Y25
N108 G80 Z20
N109 (UAO,0)
N110 (URT,0)
N111 S1000 T4.4 M6
