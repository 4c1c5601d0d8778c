(words after the ,R or ,C of a corner, decision 75)
G90 G00 X0 Y0 Z0
G01 X10 ,R2 F100
Y10 ,C1 F200
X0
M30
