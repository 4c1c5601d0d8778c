(translate-rounded: a CAM fourth decimal into pp, which writes 0.001 mm: NC4098)
G90 G01 X1.2345 Y2.5 F100.
X2.00049
X3.
M30
