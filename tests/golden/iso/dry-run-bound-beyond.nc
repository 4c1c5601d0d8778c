(the dry run of check runs the program's 6 blocks and 1000000 more: this program runs 1000008)
#1=0
WHILE [#1 LT 500002] DO1
#1=#1+1
END1
M30
