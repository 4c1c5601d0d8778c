; translate-structured-gost: GOST 20999 has no loops: a repeat of a constant count
; is written out block by block (docs/translate.md), the arcs and comments kept.
G0 X0 Y0 Z5
S800 M03
G1 F200
(RPT,2)
G91 G1 X10
(RPT,2)
; a quarter circle
G91 G2 X5 Y-5 I0 J-5
(ERP)
G90
(ERP)
G0 Z20
M30
