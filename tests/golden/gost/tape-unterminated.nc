tape-unterminated: a program must end with M02 or M30 before the next program start or the end of the file (GOST 20999 §1.9, NC1006)
%1
N1 G00 X1.
N2 X2.
%2 (a program start before M02 or M30 - program 1 is not terminated)
N1 G00 X3.
  %3 (spaces before the percent sign are not perceived - still the start of the line)
N1 G00 X4. (the file ends before M02 or M30)
