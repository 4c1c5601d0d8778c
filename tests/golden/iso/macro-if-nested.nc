(multi-line IF nested in a WHILE and in another IF body, and a GOTO into a body)
G01 X0 Y0 Z0 F100;
#1=0;
WHILE [#1 LT 3] DO1;
#1=#1+1;
IF [#1 EQ 2] {
G01 Y2;
} ELSE {
IF [#1 EQ 1] {
G01 X1;
} ELSE {
G01 X3;
}
#9=#1;
}
END1;
(a WHILE inside an IF body)
IF [#1 EQ 3] {
#2=0;
WHILE [#2 LT 2] DO1;
#2=#2+1;
G01 Z#2;
END1;
} ELSE {
G01 Z99;
}
(a GOTO into a body runs the rest of that body and then leaves the IF)
GOTO 70;
IF [#1 EQ 3] {
G01 X98;
} ELIF [#1 EQ 4] {
G01 X97;
N70 G01 X4;
G01 X5;
} ELSE {
G01 X96;
}
G01 X6;
(a GOTO out of a body)
IF [#1 EQ 3] {
G01 Y7;
GOTO 80;
G01 Y95;
}
G01 Y94;
N80 G01 Y8;
M30;
