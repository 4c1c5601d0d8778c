format-implied-run: an implied-point program (format-implied-leading) run end to end: the decoded values drive the motion
%
N1 S800 M3 (S800 = 800 rpm, non-dimension, integer)
N2 G01 X10000 Y-2500 F1500 (X = 10.0, Y = -2.5, F = 150.0)
N3 G02 X20000 I5000 (end X = 20.0; centre at I = 5.0 from the start, X 15 Y -2.5, radius 5, half circle)
N4 G00 Z25000 (Z = 25.0)
N5 G04 P2500 (dwell P = 2.5 s)
N6 G91 G01 X-1500 Y025 F15 (incremental, X -1.5, Y +0.025; F = 1.5)
N7 M02
