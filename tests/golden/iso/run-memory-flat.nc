(10^6 moves around a square with cutter radius compensation: what the runtime holds stays flat, under 1 MiB)
G90 G17 G01 X0 Y0 F1000
G41 D1 X0 Y10
#1=0
WHILE [#1 LT 1000000] DO1
#1=#1+1
G01 X[100*[[#1 MOD 4] GE 2]] Y[100*[[[#1+1] MOD 4] LT 2]+10]
END1
G40 X0 Y0
M30
