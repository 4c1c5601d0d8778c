(no F: NC4001 once, with the count of the moves after it that lack it, decision 74)
G90 G00 X0 Y0 Z0
G01 X10
G01 X20
G02 X30 Y0 R5
G01 X40 F100
G94
G01 X50
G95
G01 X60
G01 X70
M30
