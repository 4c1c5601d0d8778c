; a spline whose G06 points a loop adds without end: the points it holds grow until
; the run's memory budget stops it
N1 G0 X-10 Y-10
N2 (BSP,X,Y,0)
N3 G1 X0 Y0 F100
N4 G06 X10 Y0
"LOOP" X15 Y5
X10 Y0
(BNC,LOOP)
G1 G40 X15 Y30
(ESP)
M30
