(cutter radius compensation waits for a move in the plane, and the loop makes none)
(the events it holds grow with every block, until the run's memory budget stops it)
G90 G17 G01 X0 Y0 F100
G41 D1 X10 Y0
#1=0
WHILE [1 EQ 1] DO1
#1=#1+1
G01 Z[#1 MOD 2]
END1
M30
