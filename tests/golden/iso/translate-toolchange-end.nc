(translate-toolchange-end: ISO's M06 with the program's end in its block, which comes)
(last: the retract ISO's M06 makes first is written before the block, as for an M06)
(alone; pygcode's vertical-slot ends so)
G21 G90 G54 G17
T1 M06
S1000 M03
G00 X10. Y10. Z5.
G01 Z-1. F100.
G00 Z5.
T0 M06 M02
