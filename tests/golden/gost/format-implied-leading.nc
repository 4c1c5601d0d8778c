format-implied-leading: S-6.5 rows of X+053 and F031 without DS (implied point, leading zeros omitted, digits align right)
%
N1 G01 X01234567 F1500 (X01234567 = 1234.567; F1500 = 150.0)
N2 X1234567 F15 (X1234567 = 1234.567, right-aligned; F15 = 1.5)
N3 X-1500 F2 (X-1500 = -1.5; F2 = 0.2)
N4 X25 (X25 = 0.025)
N5 X0 (X0 = 0)
N6 X1030 (X1030 = 1.030)
N7 G1 S800 M3 (non-dimension words are integers in both modes, G1 = G01, S800 = 800, M3 = M03)
N8 G01 M05 (G01 = G01)
N9 M02
