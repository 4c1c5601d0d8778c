(a GOTO to a block number no block has: a warning, an alarm only when taken, decision 73)
G90G1X1F100
#1=1
IF[#1 EQ 2]GOTO99
G1X2
IF[#1 EQ 1]GOTO99
G1X3
M30
