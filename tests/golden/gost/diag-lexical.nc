diag-lexical: characters, comments and ignored characters (NC1001-NC1005, NC1010, NC1007)
%
N1 G01 X10 F100 (NC1001 - the star is not a tape character) *
N2 (NC1001 - lower-case letter) x5
N3 (NC1001 - a Cyrillic letter, two bytes, one column) Х5
N4 (NC1002 - this comment is not closed before the end of the block
N5 (NC1003 - 50 % of the feed)
N6 (NC1004 - ratio 1:2)
N7 X20 ) (NC1005 - a right parenthesis without a left one)
N8 X10 30 (NC1010 - read as X1030)
N9 X- 5. (NC1010 - read as X-5.)
N10 X	1.5 (no warning - HT before the first digit is not perceived)
N11 M30
text after the end of information is not read (NC1007 once)
N12 X1 *
