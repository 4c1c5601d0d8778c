%1
N1 G01 X1 F100 (a comment as Fanuc writes it)
N2 G01 X2 YЖ (and Ж)
N3 M30
