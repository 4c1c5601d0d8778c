(translate-polar-refused: a point in polar coordinates is written in X Y Z only where its radius, angle and the position are constants the text says)
G90 G17 G00 X0. Y0. Z0.
G16
#1=30.
G01 X50. Y#1 F100.
G15 G90 X10. Y10.
M98 P1000
M30
O1000
G16 X20. Y45.
M99
