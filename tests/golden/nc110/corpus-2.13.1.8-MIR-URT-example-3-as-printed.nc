; Copy of NC-110 §2.13.1.8, example 3 (seed lines 8265-8279 and 15680-15694) with its
; first block as printed in both renderings: N1 (DIS"...") has no comma after DIS and
; typographic quotes. The rest is as in corpus-2.13.1.8-MIR-URT-example-3.
; Checks: N1 is a syntax error (NC1001) at line 6, column 9 (the first quote), which
; names the character U+201D; the other blocks are correct.
N1  (DIS”...”)
N2  S1500 T5.5 M6 M3
N3  E25=0
N4  (RPT,8)
N5  (URT,E25)
N6  G X40 Y
N7  Z2
N8  G29 G1 Z-6 F150
N9  X80 F200
N10 Z-12 F150
N11 X40 F200
N12 G Z20
N13 E25=E25+45
N14 (ERP)
N15 (URT,0)
