tape-leader: everything before the first percent sign is leader and is ignored (GOST 20999 §1.8)
Деталь "вал" 12-34: set-up notes in any characters, lower case, * = # ; ( an unclosed parenthesis
N99 G00 X500. M30 : / ) - no blocks are read here either
%0001 (the program starts here)
N1 G00 X1. (the first block)
N2 M30
