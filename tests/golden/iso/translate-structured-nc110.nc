(translate-structured-nc110: Macro B as NC-110 labels, branches, RPT and EPP, docs/translate.md)
G21 G17 G90 G94 G40 G49 G80
G54 G00 X0 Y0 Z5.
#1=0
#2=2.5
WHILE [#1 LT 3] DO1
#1=#1+1
IF [#1 EQ 2 OR #2 GT 9] GOTO 10
G01 Z-1. F200
N10 G01 X[#1*10] Y[#1 MOD 2*5]
IF [#1 GE 2 AND #2 LT 3] THEN #2=#2+SQRT[4]
END1
M98 P1000 L3
#3=FIX[-2.5]+ROUND[#2*1.5]
G00 Z#3
M30
O1000
G91 G01 X[#2*2] F100
G90
M99
