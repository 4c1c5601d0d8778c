(translate-length-after-change-refused: NC-110 applies a corrector at its M06 only, so ISO's G43 after a move since the M06 is refused)
G90 G17 G00 X0 Y0 Z100
T2 M06
G00 X10 Y10
G43 H2 Z50
M30
