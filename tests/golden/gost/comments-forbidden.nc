comments-forbidden: the percent sign and the colon must not stand inside a comment (GOST 20999 §1.5, NC1003, NC1004)
%1 (title with a colon: here)
N1 G00 X1. (50 % of the feed)
N2 (time 12:30) X2.
N3 M30
