; NC-110 §2.18 (seed lines 11068-11109), decision 83: (UAV,3,VWU,XYZ,123,212): X
; drives V mirrored, Y drives W, Z drives U mirrored; all six start at 0. The manual
; gives the code alone; the moves around it are ours. The trace shows the masters; at
; (UAV,0) the slaves are where they followed them: V = -30, W = 20, U = 5.
G X0 Y0 Z0 U0 V0 W0
(UAV, 3, VWU, XYZ, 123, 212)
G X10 Y20
G1 X30 Z-5 F500
(UAV, 0)
G X0 Y0 Z0
M30
