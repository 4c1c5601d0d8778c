G87 boring (GOST 20999 Table 6): spindle start, feed in, spindle stop, manual retract to the initial level; two holes
%
N1 G90 G00 X0 Y0 Z10. (INITIAL LEVEL Z10)
N2 G87 X10. Y20. Z-6. R1. F80. S600 M03 (FIRST HOLE, THE OPERATOR RETRACTS)
N3 X30. (SECOND HOLE, THE STOPPED SPINDLE RESTARTS CW AT R)
N4 G80
N5 M30
