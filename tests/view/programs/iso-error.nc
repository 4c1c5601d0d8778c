(ncc view test: the run stops at an arc whose radius cannot reach its end point; the page lists the error and shows the path up to it)
G17 G21 G90 G54
G00 X0 Y0 Z5
G01 Z-1 F300
X30
G03 X30 Y20 R10
G02 X80 Y20 R5
G01 X0
M30
