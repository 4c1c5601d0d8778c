tape-number-length: a program number has at most 8 digits (GOST 20999 §1.6, decision 2, NC1016)
%12345678 (eight digits - accepted)
N1 M02
%00000001 (eight digits with leading zeros - accepted)
N1 M02
%123456789 (nine digits - NC1016)
N1 M02
%000000001 (nine digits, leading zeros count too - NC1016)
N1 M30
