threads-no-spindle: thread cutting needs a turning spindle, M03 or M04 with S above 0 (NC4013), pitch in mm per revolution (GOST 20999 §7.2)
%
N1 G90 G00 X10. Z5. S500 (S set, the spindle is off)
N2 G33 Z-20. K1.5 (NC4013, spindle off)
N3 G00 Z5. S0 M03 (the spindle turns at S0)
N4 G33 Z-20. K1.5 (NC4013, S0)
N5 G00 Z5. S500 (S500, the spindle turns)
N6 G33 Z-20. K1.5 (a good thread block)
N7 G00 Z5. M05 (spindle stop)
N8 G33 Z-20. K1.5 (NC4013, after M05)
N9 M02
