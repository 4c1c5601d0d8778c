; branches-cyrillic-labels: labels may be Cyrillic capitals (decision 3; §1.2.32
; L829-834 /"НАЧАЛО"N125; §1.2.34 uses НАЧАЛО and КОНЕЦ), as operands of a
; branch and of EPP, unquoted. BNC skips the message; BLT runs НАЧАЛО..КОНЕЦ
; twice; the EPP a third time: E1=3 E2=3.
(BNC,НАЧАЛО)
(DIS,"NOT REACHED")
"НАЧАЛО" E1=E1+1
"КОНЕЦ" E2=E2+1
(BLT,E1,2,НАЧАЛО)
(EPP,НАЧАЛО,КОНЕЦ)
(DIS,E1,E2)
M30
