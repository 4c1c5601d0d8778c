path-events: G08 acceleration, G09 deceleration and G63 tapping act only in the block in which they are written (GOST 20999 Table 4, Table 5)
%
N1 G90 G01 X10. F100. (no path event)
N2 G08 X20. F200. (acceleration, the G function before the F register)
N3 X30. (G08 has expired)
N4 G09 X40. (deceleration towards the programmed point)
N5 X50. (G09 has expired)
N6 G09 G08 X60. (both, in the order written)
N7 S200 M03
N8 G63 Z-10. (tapping in this block)
N9 Z0 (G63 has expired)
N10 G09 (no motion, the event alone)
N11 M02
