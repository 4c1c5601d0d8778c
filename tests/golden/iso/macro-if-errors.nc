(multi-line IF errors: ELSE after ELSE, ELIF after ELSE, a stray '}', a body without braces, ELSE without IF, a missing '}')
#1=1;
IF [#1 EQ 1] {G01 X1 F100;} ELSE {G01 X2 F100;} ELSE {G01 X3 F100;}
IF [#1 EQ 1] {G01 X1 F100;} ELSE {G01 X2 F100;} ELIF [#1 EQ 2] {G01 X3 F100;}
G01 X4 F100;
}
IF [#1 EQ 1]
G01 X5;
ELSE {G01 X6;}
IF [#1] {G01 X7;}
IF [#1 EQ 1] {
G01 X8;
M30;
