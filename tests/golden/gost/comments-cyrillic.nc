comments-cyrillic: any character but the percent sign and the colon may stand in a comment, UTF-8 Cyrillic included (GOST 20999 §1.5)
%1
N1 (Фреза Д10, деталь "вал") G00 X1.
N2 X2. (lower case, * = # ; + - / \ are text here; the / does not skip anything)
N3 M30 (Конец)
