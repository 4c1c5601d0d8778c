tape-start-own-line: a percent sign alone on its line is a program start, not a tape start marker: LF is not ignored (GOST 20999 §1.8, decision 1)
%
%0001 (so the program above has no blocks, NC1020, and is not terminated, NC1006)
N1 M30
