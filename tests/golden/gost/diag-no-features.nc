N1 (diag-no-features - a format without program-start, main-block and block-skip characters, NC1017)
N2 G01 X1 F100
/N3 X2 (NC1017 - block skip before the block)
N4 X3 /Y3 (NC1017 - block skip inside the block)
:5 X4 (NC1017 - main block)
N6 M30
