(two codes of one modal group in a block: the last is in force, decision 75)
G90 G00 X0 Y0 Z0
G00 G01 X10 F100
G91 G90 X20
M30
