%
O9020(TWO MACROS IN ONE FILE)
(checked as a library: no run with vacant arguments, decision 71)
IF[#1 EQ #0]GOTO99
#3=#2/#1
G91G1X#3F100
M99
O9021
G90G1Y#25F100
M99
%
