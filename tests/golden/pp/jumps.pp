%11 "nested G73 loops, a forward jump, counts given by parameters"
N1 R1 2 R2 1
N2 G90 G01 X1 F100
N3 G91 X1
N4 G73 L3 Q1 "N3..N4 run twice"
N5 Y1
N6 G73 L2 QR2 "N2..N6 twice (Q from R2): the inner loop is armed again"
N7 G90 G73 L9 "a forward jump: N8 does not run"
N8 X100
N9 G71 L20 QR1 "subprogram L20 twice (Q from R1)"
N10 M30
N20 G79 L20
N21 G91 Z-1
N22 G70
