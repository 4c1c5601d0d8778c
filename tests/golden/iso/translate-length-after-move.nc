(translate-length-after-move: NC-110 activates a corrector by M06 only [§2.7.7], so ISO's G43 H after a move since the M06 is the M06 of the tool in the spindle with that corrector, in a block before the G43's, and G49 that M06 with corrector 0; the next tool selected since [T3] is selected again for its M06)
G90 G17 G00 X0 Y0 Z100
T2 M06
T3
G00 X10 Y10 M03 S1000
G43 H2 Z50 M08
G01 Z10 F200
G49 G00 Z80
G43 H3 Z60
M30
