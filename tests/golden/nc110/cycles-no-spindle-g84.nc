; NC-110 Table 2.6, decision 54: G84 with no spindle direction ever programmed is
; refused at the hole (NC4027, 6:1), where `ncc run` stops. The refused hole leaves no
; direction behind: `ncc check` refuses the G86 hole at line 9 too (NC4027, 9:1).
N1 S400 F450
N2 G84 R5 Z-20
N3 X10
N4 G80
N5 G86 R5 Z-20
N6 X10
N7 G80
