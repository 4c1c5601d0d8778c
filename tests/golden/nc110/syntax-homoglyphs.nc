; syntax-homoglyphs: letters must be those of Table 2.1 (§2.4.1, seed L1398-1424):
; a Cyrillic letter that looks like a Latin one is NC1027 naming the Latin letter
; (decision 2); a lower-case letter other than the fourteen a b c d l m o p r s t u v w
; is NC2019; letters are case-sensitive. The manual's own misprints are used where it
; has them: L1534 Е30, L1535 р2, L7789 ТЕ14.Е15, L7780 МЕ3, §2.10.1 ТMR.
; Cyrillic Е (U+0415) starting an assignment
Е30 = 28.5
; Cyrillic р (U+0440) for the GTL point p2
р2 = X10 Y25
; Cyrillic Т (U+0422) for T (only the first look-alike of a block is reported)
ТЕ14.Е15
; Cyrillic М (U+041C)
МЕ3
; Cyrillic Х (U+0425) in an ISO block, column 4
G1 Х10 F100
; Cyrillic Т in a system variable name
ТMR = 12.5
; Cyrillic Е inside an expression, column 7
E1=E2+Е3
; lower-case letters outside the fourteen: x, g, z (NC2019)
x10
g1 X1
G1 X1 z2 F100
; case matters for names too: sin and Tmr are not the function SIN and the variable TMR
E30=sin(30)
Tmr=2
; Cyrillic letters are fine in a comment, in a text and in a label: no error here
;Е30 = 28.5
(DIS,"Е30")
"ПУСК" E1=1
