; corpus-2.13.3.2-epp-example-3-label: corpus-2.13.3.2-epp-example-3 (the GTL
; figure replaced by a G01 triangle, see there) with the label as printed:
; '"Z" N56' (OCR for "2"). Label 2 is then undefined: expected NC3010 at the
; operand 2 of N59 (line 18 col 12) and of N62 (line 21 col 12), and nothing
; else (ncc check; seed L8978-8995, corpus digest §2.13.3.2 example 3).
N32 F200 S1200 T1.1 M6 M3
N40 (UOT,0,X50,Y50)
"1" N41
N42 G1 X Y
N43 Z-10
N44 X50 Y
N50 X25 Y25
N52 X Y
N54 Z2
"Z" N56
N57 (UOT,0,X-50,Y)
N58 (URT,30)
N59 (EPP,1,2)
N60 (UOT,0,X,Y-50)
N61 (URT,-30)
N62 (EPP,1,2)
N63 (URT,0)
N64 (UAO,0)
N65 GZ 2
N66 M30
