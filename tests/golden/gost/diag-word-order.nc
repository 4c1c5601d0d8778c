diag-word-order: the recommended word order of §2.2 in pedantic mode (NC3006)
%
N1 G01 X1 Y2 Z3 F100 S200 T1 M03 (the recommended order - no warning)
N2 Y3 X4 (NC3006 - X before Y)
N3 F100 X5 G01 (NC3006 twice - each word against the one before it)
N4 X6 F200 A2 (NC3006 - A before F)
N5 M05 S0 (NC3006 - S before M)
N6 M30
