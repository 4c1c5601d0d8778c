m-m06: T selects a tool, M06 loads it after the motion of its block (GOST 20999 Tables 7-8); with m06_stops_spindle it also stops the spindle and coolant
%
N1 G00 S800 M03 M08
N2 X10. T1 M06 (T before the move, the change after it)
N3 T2 (selects only)
N4 M06 (loads tool 2)
N5 T3 M03 M06 (M03 starts before, M06 acts after)
N6 M30
