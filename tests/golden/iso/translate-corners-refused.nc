(translate-corners-refused: the next block must be a move in the plane under G90 with constant words, read with this one)
G90 G00 X0. Y0. Z0.
G01 X20. F100. ,C5.
G91 Y20.
G90 G01 X0. ,R2.
#1=10.
Y#1
M30
