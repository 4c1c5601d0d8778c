Codes chosen by R parameters: G01 and G00 are both of group G0.
%1
N1 R1 1 R2 0
N2 GR1 GR2 X1
N3 G73 L2
N4 M30
