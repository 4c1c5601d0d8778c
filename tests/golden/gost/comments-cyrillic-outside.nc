comments-cyrillic-outside: outside a comment a Cyrillic letter is not allowed; NC1001 names it (GOST 20999 Tables 1-3)
%1
N1 G00 X1. (Фреза - inside the comment it is text)
N2 X2. Фреза
N3 М30 (a Cyrillic М that looks like the Latin M)
N4 M30
