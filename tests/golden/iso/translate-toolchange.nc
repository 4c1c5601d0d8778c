(translate-toolchange: ISO's M06 stops the spindle and coolant and takes Z to the reference point first: into pp as M05, M09, G30 Z0, then M06; into NC-110 and GOST, which have no reference-point code, as M05, a rapid in machine coordinates, G79 or G53 G00 Z0, and the motion code again)
G21 G17 G90 G54
T1 M06
S1000 M03
M08
G00 X10 Y10 Z5
G01 Z-1 F100
T2
M06
S500 M03
G00 X20
M30
