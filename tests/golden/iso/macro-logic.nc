(comparisons and logic: EQ NE GT GE LT LE and == <> > >= < <=, AND OR XOR and & |, precedence)
#1=30;
#2=50;
G01 X0 Y0 Z0 F100;
(the seed's example: #1 LE #2 AND #2 GT 45 is [#1 LE #2] AND [#2 GT 45])
IF [#1 LE #2 AND #2 GT 45] THEN G01 X1;
IF [#1 LE #2 AND #2 GT 55] THEN G01 X2;
(word forms and symbol forms)
IF [#1 EQ 30] THEN G01 Y1;
IF [#1 == 30] THEN G01 Y2;
IF [#1 NE 30] THEN G01 Y3;
IF [#1 <> 30] THEN G01 Y4;
IF [#1 GT 30] THEN G01 Y5;
IF [#1 > 29] THEN G01 Y6;
IF [#1 GE 30] THEN G01 Y7;
IF [#1 >= 31] THEN G01 Y8;
IF [#1 LT 30] THEN G01 Y9;
IF [#1 < 31] THEN G01 Y10;
IF [#1 LE 29] THEN G01 Y11;
IF [#1 <= 30] THEN G01 Y12;
(AND &, OR |, XOR)
IF [#1 EQ 30 & #2 EQ 50] THEN G01 Z1;
IF [#1 EQ 30 AND #2 EQ 51] THEN G01 Z2;
IF [#1 EQ 31 OR #2 EQ 50] THEN G01 Z3;
IF [#1 EQ 31 | #2 EQ 51] THEN G01 Z4;
IF [#1 EQ 30 XOR #2 EQ 50] THEN G01 Z5;
IF [#1 EQ 30 XOR #2 EQ 51] THEN G01 Z6;
(AND binds tighter than OR: true OR [false AND false])
IF [#1 EQ 30 OR #1 EQ 0 AND #2 EQ 0] THEN G01 Z7;
IF [[#1 EQ 30 OR #1 EQ 0] AND #2 EQ 0] THEN G01 Z8;
(arithmetic binds tighter than comparison)
IF [#1+20 EQ #2] THEN G01 Z9;
IF [#1*2 GT #2+5] THEN G01 Z10;
(the value of a comparison and of AND/OR in an assignment)
#3=#1 LT #2;
#4=#1 GT #2;
#5=[#1 LT #2] OR [#1 GT #2];
#6=[#1 LT #2] AND [#1 GT #2];
G01 X#3 Y#4 Z#5;
G01 X#6 Y0 Z0;
(on numbers AND OR XOR are boolean, not bitwise: 6 AND 3 is 1, 6 XOR 3 is 0)
#7=6 AND 3;
#8=6 XOR 3;
#9=0 OR 0;
G01 X#7 Y#8 Z#9;
M30;
