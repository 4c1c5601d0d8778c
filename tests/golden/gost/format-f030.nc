format-f030: the ambiguous item F030 reads as leading zeros omitted, 3 integer digits, no fraction (warning NC2010 when the profile loads)
%
N1 G01 X1 F150 (F150 = 150)
N2 X2 F5 (F5 = 5)
N3 X3 F015 (F015 = 15)
N4 M02
