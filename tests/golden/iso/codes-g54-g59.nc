(G54-G59, spec 8.15: each selects its work offset of the profile codes-wcs.toml, alone or with a move; positions are in the selected system, an axis not written keeps its machine position; expected: G56 X10 Y50, G59 X1.5 Y2.5 Z0)
G90 G00 X0 Y0 Z0;
G55;
X0 Y0 Z0;
G56 X10;
G57 G01 X0 Y0 Z0;
G58 G00 X0 Y0 Z0;
G59 Z0;
G54 X0 Y0 Z0;
M30;
