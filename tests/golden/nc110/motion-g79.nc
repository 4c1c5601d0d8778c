; G79: machine coordinates (§2.8.10, L4266-4300; decision 46), profile motion-origin
; (origin 0 at machine X100 Y50). G79 words are machine coordinates with no origin, scale,
; mirror or rotation; the centre I J of a G79 arc too; the G90/G91 before it returns.
; N1-N2 mirror X and rotate 90 degrees: N3's X10 Y0 maps to X-10 Y0 then X0 Y-10 (the
;   trace shows the position from the origin after the transforms, decision 28).
; N4 G79 X70 Y55: machine X70 Y55, shown X-30 Y5 (not mirrored, not rotated).
; N5 G79 G1: machine X80 Y55 (X-20 Y5).
; N6 G79 G2 about machine X85 Y55 (shown X-15 Y5), radius 5, clockwise (the mirror does
;   not turn it), 180 degrees, to machine X90 Y55 (X-10 Y5).
; N7 G1 X0 Y0 is a program point again: machine X100 Y50, shown X0 Y0 (G90 is back).
N1 (MIR,X)
N2 (URT,90)
N3 G0 X10 Y0
N4 G79 X70 Y55
N5 G79 G1 X80 Y55 F100
N6 G79 G2 X90 Y55 I85 J55
N7 G1 X0 Y0
N8 (MIR)
N9 (URT,0)
