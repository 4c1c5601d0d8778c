tape-crlf: CR LF line ends; CR is not perceived (GOST 20999 Table 2 note 2)
%1 (every line of this file ends with CR LF)
N1 G00 X1. (a comment)
N2 Y1 0. (NC1010 - the source line is shown without CR)
N3 M30
