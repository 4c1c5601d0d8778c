diag-format-ambiguous: the profile's format has F030 (NC2010 when the profile is read)
%
N1 G01 X10 F150 (F030 reads 3 integer digits - 150)
N2 M30
