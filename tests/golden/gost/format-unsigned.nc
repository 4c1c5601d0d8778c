format-unsigned: X53 without DS: no sign, exactly 8 digits (S-6.5)
%
N1 G00 X00005000 (5)
N2 M02
