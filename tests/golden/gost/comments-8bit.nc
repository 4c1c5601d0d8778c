comments-8bit: comments may hold 8-bit text (KOI8-R) and tabs; JSON escapes them (decision 9)
%
N1 G00 X1. (Переход)
N2 (a	b) M30
