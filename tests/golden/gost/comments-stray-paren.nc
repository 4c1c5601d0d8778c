comments-stray-paren: a closing parenthesis without an opening one means process from here, no effect (GOST 20999 Table 2, decision 7, NC1005)
%1
N1 G00 X1.) Y2.
N2 ) X3.
N3 M30
