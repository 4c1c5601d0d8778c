modal-spindle-modes: G96 constant cutting speed (S in m/min), G97 revolutions per minute (GOST 20999 Table 4 group l, Table 5, §3.3.4)
%
N1 G97 S800 M03 (800 rpm)
N2 G96 S150 (150 m/min)
N3 G00 X10. S180 (a new cutting speed under G96)
N4 G97 S1200 (1200 rpm again)
N5 M30
