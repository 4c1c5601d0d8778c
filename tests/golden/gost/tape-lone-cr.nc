tape-lone-cr: a CR without LF is not perceived and does not end the block (GOST 20999 Table 2 note 2)
%1
N1 G00 X1.N2 X2. (one block - N2 is not first, NC1012, and X repeats, NC3001)
N3 M30
