comments-unterminated: a comment lies within one block; an unclosed one is an error (GOST 20999 §1.5, §1.7, decision 6, NC1002)
%1
N1 G00 X1. (not closed
N2 X2. (the next line is read as a new block)
N3 M30
