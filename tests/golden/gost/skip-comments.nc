skip-comments: a comment after a mid-block / is skipped with the rest of the block (GOST 20999 Table 2)
%
N1 G00 X1. (before) / Y1. (after)
N2 M30
