format-unsigned-errors: X53 has no '+': a sign, even '+', is NC2003 (S-6.5, §9.2)
%
N1 G00 X-5 (NC2003)
N2 X+5 (NC2003)
N3 M02
