; translate-own: NC-110 into NC-110 keeps its three-letter codes of a function and its memories and system variables as written
(UOT,1,X-250,Y-50)
(URT,30)
(MIR,X)
SA3.IN=5
E30=SA3.IN+2
SYVAR1=E30
TMR=0.5
G00 X10 Y10
G04
(MIR)
(URT,0)
(UOT,1,X0,Y0)
M02
