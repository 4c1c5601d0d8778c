(A syntax error drops its block, which holds no N1: GOTO1 is still reported)
IF[#1LT#2]GOTO1
WQ[[#1GE#2]OR[#1EQ#2]]DO1
#1=#1+1
END1
M30
