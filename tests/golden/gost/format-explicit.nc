format-explicit: S-6.5 rows of X+053 accepted with DS (default profile); a word without a point is an integer (§3.1.4)
%
N1 G01 X-1500 F15 (-1500; F051, F15 = 15)
N2 X25 F2 (25; F2 = 2)
N3 X0 (0)
N4 X12.5 F150.5 (12.5; F150.5 = 150.5)
N5 X.03 (0.03, §3.1.5)
N6 X1030. (1030.0, §3.1.5)
N7 X1030 (1030, §3.1.4)
N8 X1.2500 (1.25, trailing zeros after the point are insignificant)
N9 X-0 (-0 = 0)
N10 M02
