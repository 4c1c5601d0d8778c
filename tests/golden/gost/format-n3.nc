format-n3: block number format N3: exactly three digits (S-6.5)
%
N005 G00 X1 (N005 = 5)
N010 X2 (10)
N999 M02 (999)
