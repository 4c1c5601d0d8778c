; NC-110 §2.8.9 with the frame of §2.13.1 (decision 28): hole positions go through the
; active origin, rotation and mirror like any point; R and the depth are coordinates of
; the drilling axis, measured from the active origin (the trace shows positions from the
; active origin, after mirror and rotation).
; Profile cycle-mill: the tool starts at machine X0 Y0 Z100.
; N2: temporary origin at machine X100 Y50 Z-10, so the tool is at Z110 from it.
; N3: rotation by 90 degrees about the origin.
; N5: program (10,0) is (0,10): XY at Z110, rapid to Z2, feed to Z-8, rapid to Z2.
; N6: program (20,5) is (-5,20): XY at Z2, feed to Z-8, rapid to Z2.
; N7: cancel, up to Z30. N8-N9: no rotation, mirror X.
; N11: program (10,5) is (-10,5): XY at Z30, rapid to 2, feed to -8, rapid to 2.
N1 S800 F100 M3
N2 (UOT,0,X100,Y50,Z-10)
N3 (URT,90)
N4 G81 R2 Z-8
N5 X10 Y0
N6 X20 Y5
N7 G80 Z30
N8 (URT,0)
N9 (MIR,X)
N10 G81 R2 Z-8
N11 X10 Y5
N12 G80
N13 (MIR)
