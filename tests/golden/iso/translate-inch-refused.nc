(translate-inch-refused: pp has no inch mode, so a length in inches must be a constant the translation can convert, in a unit it knows)
G20 G90 G00 X1. Y1.
#1=0.5
G01 X#1 F10.
M98 P1000
M30
O1000
G01 Y2.
M99
