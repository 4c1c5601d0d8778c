(ncc plot of a program with an error: the drawing ends before the first block with errors, the moves after it are not drawn, the error is reported once and the exit status is 1)
G90 G00 X0 Y0 Z5
G01 Z-1 F100
X10
G01 X20 Y
X30 Y10
M30
