(translate-spindle-stop: ISO's M05 leaves the coolant on, NC-110's and GOST's M05 end it)
(too. Where the next block ends the coolant or the program before anything moves, theirs)
(runs the same: a CAM program's M05 before its M09 or M30)
G21 G90 G54
T1 M06
S1000 M03
M08
G00 X10. Y10. Z5.
G01 Z-1. F100.
G00 Z5.
M05
M09
S2000 M03
M08
G01 X20. Z-1.
G00 Z5.
M05
M30
