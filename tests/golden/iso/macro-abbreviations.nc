(Fanuc's two-letter macro words, decision 70)
#1=0
WH[#1 LT 2]DO1
#1=#1+1
END1
IF[#1 EQ 2]TH #2=SQ[16]+AB[-1]+RO[1.4]+FI[-1.5]+FU[1.2]
#3=SI[90]+CO[0]+TA[45]+AS[1]+AC[1]+AT[1]/[1]+EX[0]
#4=[#1 EQ 2]AN[#2 EQ 6]
#5=[#1 EQ 2]XO[#2 EQ 6]
GO10
G1X99F100
N10 G1 X#2 Y#3 Z#4 F100
G1 X#5
M30
