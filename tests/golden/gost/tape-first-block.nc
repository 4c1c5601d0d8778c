tape-first-block: the first block after the program start needs a block number (GOST 20999 §1.4, decision 5, NC1015)
%1
G00 X1. (no block number - NC1015, a warning; an error with mode = "strict")
X2. (only the first block of a program must have one)
N3 M02
%2

N1 G00 X3. (blank lines are not blocks - this is the first block of program 2)
N2 M02
%3
:1 G90 G17 G00 X4. F100 S100 M03 T1 (a main block number is a block number)
N2 M30
