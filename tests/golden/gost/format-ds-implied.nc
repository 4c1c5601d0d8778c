format-ds-implied: DS with ds_integer_rule = implied: a word with a point is decimal, one without is read by the implied point
%
N1 G01 X1500 F1500 (X+053, 1.5; F051, F1500 = 150.0)
N2 X-1500 F150.5 (-1.5; F150.5 = 150.5)
N3 X25 (0.025)
N4 X1030 (1.030)
N5 X01234567 (1234.567)
N6 X0 (0)
N7 X12.5 (12.5)
N8 X.03 (0.03)
N9 X1030. (1030.0)
N10 X1.2500 (1.25)
N11 G1 S800 M3 (non-dimension words stay integers, G01, 800, M03)
N12 M02
