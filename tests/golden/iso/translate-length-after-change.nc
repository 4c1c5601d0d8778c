(translate-length-after-change: ISO's G43 H in the block after its M06, where nothing moves between, is NC-110's corrector in the T word of the M06, T2.2 M06; ISO's G53 is NC-110's G79, the block in machine coordinates. Expected in machine coordinates, offset 2 is 110 long: Z0 for the change, Z50 with the offset, Z0 in machine coordinates, X-10 Y-10 there)
G90 G17 G00 X0 Y0 Z100
T2 M06
G43 H2
G00 Z50
G53 G00 Z0
G53 X-10 Y-10
M30
