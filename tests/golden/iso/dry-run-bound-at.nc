(the dry run of check runs the program's 6 blocks and 1000000 more: this program runs exactly 1000006)
#1=0
WHILE [#1 LT 500001] DO1
#1=#1+1
END1
M30
