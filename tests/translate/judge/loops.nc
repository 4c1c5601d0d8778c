; loops: E parameters, RPT loops two deep, a forward branch and a backward one,
; as a structured translation keeps them (judge_linuxcnc.py).
E30=0
E31=12.5
E1=3
G0 X0 Y0 Z5
G1 F300
(RPT,E1)
E30=E30+1
(RPT,2)
G91 XE31
G90
(ERP)
(BEQ,E30,2,SKIP)
G0 ZE30
"SKIP" G1 YE30
(ERP)
E32=0
"TOP" E32=E32+1.5
E33=E32*E32-SQR(E32)
G1 XE32 YE33
(BLT,E32,6,TOP)
M30
