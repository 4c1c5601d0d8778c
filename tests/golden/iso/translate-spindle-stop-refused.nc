(translate-spindle-stop-refused: an M05 the coolant runs on after, through a move:)
(NC-110's M05 would end it there)
G21 G90 G54
T1 M06
S1000 M03
M08
G00 X10. Y10. Z5.
M05
G00 Z50.
M09
M30
