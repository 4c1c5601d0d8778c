; NC-110 §2.19, decision 83: (UAV,4,XYZ,UVW,a1,a2,a3) turns the coordinate system in
; space: real = Rz(a3) Ry(a2) Rx(a1) virtual, about the origin, counter-clockwise
; positive (the manual has no example; the order of the rotations is ours). Profile uav.
; N2: a3 = 90 at X10 Y0 Z0: virtual = Rz(-90) real: U0 V-10 W0. N3-N4 go to U10 V10;
;   N5 cancels there: X = -10, Y = 10 (U10 V10 turned by 90 degrees), U V W back to 0.
; N7: a1 = 90, a3 = 90: R = Rz(90) Rx(90) takes U to Y, V to Z, W to X; at X0 Y0 Z0 the
;   virtual axes are 0. N8 moves U10 V5 W2: N9 cancels at X2 Y10 Z5.
N1 G X10 Y0 Z0
N2 (UAV,4,XYZ,UVW,0,0,90)
N3 G1 U10 V0 F500
N4 V10
N5 (UAV,0)
N6 G X0 Y0 Z0
N7 (UAV,4,XYZ,UVW,90,0,90)
N8 G1 U10 V5 W2
N9 (UAV,0)
N10 M30
