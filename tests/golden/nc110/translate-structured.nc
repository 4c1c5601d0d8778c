; translate-structured: what a structured translation keeps (docs/translate.md).
; E parameters become #500 on, an IN store is rounded, RPT is a loop of the
; target, branches are jumps (ISO) or o-word blocks (LinuxCNC), T1.4 M06 is the
; tool with its length G43 H4, DIS a comment with a warning.
E10=7/2
E30=0
E31=12.5
E1=3
T1.4 M06
G0 X0 Y0 Z5
S1000 M03
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
E33=E32*E32-SQR(ABS(E32))
G1 XE32 YE33
(BLT,E32,6,TOP)
(DIS,"E10=",E10)
G0 Z20
M05
M30
