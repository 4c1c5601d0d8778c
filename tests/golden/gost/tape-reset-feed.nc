tape-reset-feed: after M02 the feed is unset and G01 is in force again, so a move without F is an error (GOST 20999 §8, §3.3.3, decisions 4, 19, NC4001)
%1
N1 G01 X10. F200 (a feed move with F200)
N2 G00 X20. (rapid mode at the end of program 1)
N3 M02
%2
N1 X5. (G01 again and no F - NC4001)
N2 M30
