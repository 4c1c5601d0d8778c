tape-empty-program: a program without blocks (NC1020); blank lines are not blocks (GOST 20999 §1.4, §1.9)
%1 (no blocks - NC1020, and NC1006 since nothing ends it)
%2 (only blank lines, one of spaces and a tab - still no blocks)

   	
%3
N1 M30
