(streamed blocks keep their labels: GOTO back to one, a computed GOTO to one)
N10 G00 X0 Y0 Z5
N20 G01 X10 F100
N30 G01 Y10
#1=#1+1
N40 G01 X0
IF [#1 LT 3] GOTO 20
#2=40
#3=#3+1
IF [#3 LT 2] GOTO #2
M30
