modal-planes: G17/G18/G19 (GOST 20999 Table 4 group c, Table 5): each selection is a plane event; an arc runs in the plane in force
%
N1 G00 X10. (contouring power-on state is G17, not an event)
N2 G18 (plane ZX)
N3 G03 X0 Z10. I-10. F100. (ZX arc about Z0 X0, ccw seen from +Y, from the X axis to the Z axis = 270 deg)
N4 G19 (plane YZ)
N5 G02 Y10. Z0 K-10. (YZ arc about Y0 Z0, cw seen from +X, 90 deg)
N6 G17 G03 X-10. Y0 J-10. (G17 acts in its own block - XY arc about X0 Y0, 90 deg)
N7 G17 (selecting the plane in force again is still recorded)
N8 M30
