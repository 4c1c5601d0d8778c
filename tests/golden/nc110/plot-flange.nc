; A flange: six holes on a bolt circle of radius 40 about X100 Y80, drilled with
; G81 under a rotation that the loop turns by 60 degrees a hole (NC-110 dialect).
N1 (DIS,"FLANGE, 6 HOLES D8.5")
N2 T2.2 M6
N3 S1200 M3 F150
N4 G Z20
N5 E1=6
N6 E25=0
N7 E26=360/E1
N8 (UOT,0,X100,Y80)
N9 G81 R2 Z-12
N10 (RPT,E1)
N11 (URT,E25)
N12 X40 Y0
N13 E25=E25+E26
N14 (ERP)
N15 G80 Z20
N16 (URT,0)
N17 (UAO,0)
N18 (DIS,"DONE AT ",E25," DEGREES, ",TIM0," S")
N19 G Z100 M5
N20 M30
