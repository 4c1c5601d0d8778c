(a GOTO and an M97 to streamed blocks: the number used twice, a call before M30)
N10 G00 X0 Y0
N20 G01 X10 F100
N10 G01 Y10
N30 X5
IF [#1 EQ 1] GOTO 10
M97 P30
M30
