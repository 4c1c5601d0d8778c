%1 "hostile-cyrillic: a letter outside a comment is reported once"
N1 G00 X1 Ж
N2 M30
