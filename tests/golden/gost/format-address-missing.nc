format-address-missing: E, L and O are not in the default profile's descriptor (NC2001)
%
N1 G01 X10 F100 E5 (E, second feed function, not in the format)
N2 L1 (L, undefined in Table 1, not in the format)
N3 O7 (O, undefined in Table 1, not in the format)
N4 M02
