comments-tab: comments may hold Cyrillic (UTF-8) and tabs; JSON escapes the tab (decision 9).
%
N1 G00 X1. (ПЕРЕХОД)
N2 (a	b) M30
