modal-units: G71 mm / G70 inch (profile unit_codes, GOST 20999 §3.2.2, §8); positions and feeds are printed in the program's unit
%
N1 G71 G00 X25.4 Y12.7 (millimetres)
N2 G70 (inches - the current point is now X1 Y0.5)
N3 G00 X2. (X in inches, Y still 12.7 mm = 0.5 in)
N4 G01 Y1. F10. (F in inches per minute, printed as programmed)
N5 G71 (back to millimetres - the current point is X50.8 Y25.4)
N6 G00 Z-25.4
N7 G91 G70 X1. (one inch more from X2 in, in the block that selects inches)
N8 G71 G01 X-25.4 F250. (one inch back, written in millimetres)
N9 M30
