; translate-structured-pp: what pp keeps (docs/translate.md): E parameters as R
; words and G26-G29 formulas, RPT as G73's counted jump back, nested.
E30=2.5
E31=-E30*4+1.25
G0 X0 Y0 Z5
S1000 M03
G1 F300
(RPT,3)
G91 XE30 YE31
(RPT,2)
G91 Z-1
G90
(ERP)
E30=E30+0.5
(ERP)
G0 Z20
M05
M30
