%7 "every function the runtime runs for pp (docs/dialects/pp.md)"
N1 G92 G55 X0 Y0 Z0 "G55 names the shift loaded; G53 stays selected"
N2 G01 X5 F100
N3 G55 X0
N4 G92 Z10 "no G5 word: the selected shift, G55"
N5 G74 X40 "diameter programming: X40 is radius 20"
N6 G91 X-10
N7 G90 G75 X40
N8 G36 X2 Y3 "scale: X by 2, Y by 3"
N9 G01 X10 Y10
N10 G37 X5 "independent shift: the program zero moves by X5"
N11 G01 X0 Y0
N12 G35 Y0 "mirror Y: the transformations add up"
N13 G01 Y10
N14 G34 X1 Y1 "cancel all; X1 Y1 is a move"
N15 M50 M07 "coolant 3 before the motion"
N16 M51 X2
N17 M53 X3 "coolants 3 and 4 off after the motion"
N18 M52
N19 M37 X4 "feed 1:100"
N20 M36 H12 P3 M23 "H, P and M23 (group M14) go to the machine's logic"
N21 G30 X0 Z0 "X and Z to the reference point"
N22 G55 X0 Y0 Z0
N23 G10 K2 "helix pitch 2"
N24 G09 G02 X10 Y0 I5 J0 Z-1 "half a turn: 1 mm down"
N25 G03 X0 Y0 I-5 J0 Z-4 K6 "K in the block: half a turn of pitch 6 is 3"
N26 D1 &0012 "Z plus, axis 4 minus the length of D1"
N27 &2 "right-aligned: 0002"
N28 &0
N29 G01 G24 X1 "exact stop, then smooth again"
N30 G23 X2
N31 G95 F0.25 S1000 M03 X3
N32 G97 F1.5 S120 X4
N33 G96 F2000 X5
N35 G24 X6
N36 G09 X7 "G09 replaces G24 in group G2: smooth again"
N37 G36 X2
N38 G92 X10 "under a scale too, the tool reads X10 here"
N39 G01 X10 "so X10 does not move"
N40 G34 G30 X0 "the scale off; G30 named without a move"
N41 G30 "no axis: nothing moves"
N42 M30
