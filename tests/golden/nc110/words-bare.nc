; words-bare: an address without a value means zero for G, the axes, I, J, K and R
; (§2.4.3 seed L1441; decision 4). The manual's own blocks are used: L1566 G Z80 X80,
; L4788 G X Y30, L8712 GZ 20, L9122 G3 X Y.. I J.., L4651 G G27 X100 Y100, L8714 XYM 30.
; start: linear X10 Y20 Z30
G1 X10 Y20 Z30 F100
; G alone is G00: rapid X80 Y20 Z80
N3 G Z80 X80
; rapid X0 Y30 Z80
N6 G X Y30
; rapid to Z20 (a blank between address and value)
GZ 20
G1 X10 Y0
; bare I and J: the centre is X0 Y0 (absolute under G90): arc ccw from X10 Y0 to X0 Y10,
; radius 10, sweep 90
N502 G3 X Y10 I J
; G with G27: rapid X100 Y100 Z20
N9 G G27 X100 Y100
; bare axes under G91 add nothing: a linear move of length zero to X100 Y100 Z20
G91 G1 X Y Z
G90 G0 X5
; X and Y bare, M30: rapid X0 Y0 Z20, then the end
N20 XYM 30
