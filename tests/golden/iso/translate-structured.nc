(translate-structured: Macro B in LinuxCNC's o-words, docs/translate.md)
G21 G17 G90 G94 G40 G49 G80
G54 G00 X0 Y0 Z5.
#1=0
WHILE [#1 LT 3] DO1
#1=#1+1
IF [#1 EQ 2] GOTO 10
G01 Z-1. F200
N10 G01 X[#1*10] Y[#1 MOD 2*5]
END1
#2=0
DO1
#2=#2+1
IF [#2 GT 2] GOTO 20
G65 P1000 A#2 B[FIX[-2.5]]
END1
N20 G00 Z20.
M30
O1000
G01 X[#1*5] Y#2 Z-0.5
M99
