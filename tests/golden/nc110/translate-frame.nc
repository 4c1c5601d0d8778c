; translate-frame: MIR, URT and SCF into a target without them, written into the points.
; Expected: (MIR,Y) 10,-10; with (URT,90) 0,10; (SCF,2) 10,10 Z2, then cw to 30,10
; about 20,10; at the end 30,10 Z5.
G0 X0 Y0 Z5
(MIR,Y)
G1 X10 Y10 F100
(URT,90)
G1 X10 Y0
(URT,0)
(MIR)
(SCF,2)
G1 X5 Y5 Z1
G2 X15 Y5 I10 J5
(SCF)
G0 Z5
