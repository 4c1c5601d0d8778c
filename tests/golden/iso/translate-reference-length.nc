(translate-reference-length: G28 with a length offset on. The machine coordinates of)
(NC-110's G79 and GOST's G53 take none: the offset ends before the move and is applied)
(again after it, as ISO's G28 keeps it; NC-110 by the M06 of the tool it has. G28 without)
(words takes every axis straight there: pp's G30 names X Y Z)
G21 G90 G54 G17
T2 M06
G43 H2 Z50.
S1000 M03
G00 X10. Y10.
G01 Z-1. F100.
G91 G28 Z0.
G90 G00 X20. Z5.
G28
G00 X5.
M30
